// The named critical points of a path, found after the run on its converged points and located
// events (docs/theory/continuation.md 14; issue 15 item 4):
//  * the onset of geometric nonlinearity: the first depth where |T(h) - T_lin(h)| reaches a
//    fraction f of |T_lin(h)| (path.nonlinearity_fraction, default 0.05), T_lin the force of the
//    same case with linear kinematics at the same depth - computed exactly, by the linear fast
//    path at each depth (linear_indentation.hpp), not by a secant: the linear stiffness changes
//    with each node entering contact. The crossing is located by re-solving the run's problem at
//    trial depths from the state of the point before it (OnsetWatch keeps it during the run);
//    failing that, on the cubic Hermite interpolant of T with the points' exact slopes dT/dh, the
//    error bound then being the distance to the root found with the linear interpolant (the
//    Hermite root is O(dh^4), the linear one O(dh^2)), or the bracket itself where a slope is
//    unknown or the contact set changes inside it;
//  * the inflections of T(h): extrema of the tangent stiffness dT/dh (kStiffnessMin where it has
//    a minimum) that hold at the curve's scale: the stiffness rises (falls) by 5 % of its
//    extreme value on both sides (stiffness_wells.hpp). In a well on one contact set, the sign
//    change of d2T/dh2 resolved by the curve-feature rules (grid_features.hpp: never inside
//    roundoff); across contact kinks, the vertex of the parabola fitted to the well's stiffness,
//    its accuracy twice the vertex's standard error;
//  * limit points: the continuation's located depth turns (dh/ds = 0) and force extrema
//    (dT/ds = 0, the limit points of the same shell under force control);
//  * bifurcations (path.stability): the located stability changes whose depth does not turn.
// "None" is an answer (empty lists, OnsetStatus::kNone), said as such by io/.
#pragma once

#include <functional>
#include <memory>

#include "analysis/critical_point.hpp"
#include "analysis/indentation_run.hpp"

namespace si {

// T_lin(h): the whole-shell force (N) of the linear-kinematics case at depth h (mm).
using LinearForce = std::function<double(double depth)>;
// The run's own force at depth h solved exactly, from the converged point at depth `from` (the
// bracket's start); false if it cannot (that point's state was not kept, or no convergence).
using ExactForce = std::function<bool(double from, double h, double& force)>;

// The onset on `points` (the first passage of the depth; `force_slope` = the position of force_N
// among the points' depth_slopes, -1 if none), with the deviation's largest value. With `exact`,
// the crossing is located by solves at the trial depths (accuracy: the final bracket, <= 1e-9
// mm), else (or where a solve fails) on the Hermite interpolant as the header says.
void find_nonlinearity_onset(const std::vector<PathPoint>& points, int force_slope,
                             const LinearForce& linear, double fraction, CriticalPoints& out,
                             const ExactForce& exact = {});

// Keeps, during a run, the states on both sides of the point where the force first departs from
// the linear-kinematics force by the fraction (the onset's bracket), so that the onset can be
// solved exactly after the run (onset_watch.hpp); holds the case's linear twin. Null for a case
// without an onset (linear kinematics, a local law, a support frame).
class OnsetWatch;
std::shared_ptr<OnsetWatch> watch_onset(const IndentationSetup& setup);
void watch_point(OnsetWatch& watch, const PathPoint& point, const cont::Vector& z);
// The run's callback with `watch` fed every point first (a null watch: the callback itself).
PathCallback watching(const std::shared_ptr<OnsetWatch>& watch, const PathCallback& callback);
// The run's first step from the twin's state at its depth (OnsetWatch::linear_state), for
// IndentationProblem::set_first_step_start; holds the watch. A null watch: none.
IndentationProblem::FirstStepStart first_step_from_twin(const std::shared_ptr<OnsetWatch>& watch,
                                                        const IndentationProblem& problem);

// The stiffness extrema of T(h) on `points` (force_slope as above: exact slopes where known), in
// depth order.
std::vector<CriticalPoint> force_inflections(const std::vector<PathPoint>& points, int force_slope);

// Limit points and bifurcations among a run's events (force = the force_N monitor's position in
// the events' monitors).
void collect_event_points(const std::vector<cont::Event>& events, int force, CriticalPoints& out);

// All of them for a run of `setup` (its linear-kinematics twin built here when the run is
// nonlinear and has no local law).
// `watch`: the run's OnsetWatch (null: the onset is located on the points only).
CriticalPoints find_critical_points(IndentationSetup& setup, const PathResult& result,
                                    OnsetWatch* watch = nullptr);

}  // namespace si
