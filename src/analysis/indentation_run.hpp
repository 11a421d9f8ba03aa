// A depth path of a case file, end to end: the model, the indenter at its pose, the contact
// problem, and the path method (docs/case-file.md `path`, `contact`):
//  * linear kinematics: the linear fast path (linear_indentation.hpp) at each depth of the grid
//    - exact for the linear problem, which has no limit points, so `path.method` is not needed;
//    with a power-law local contact (contact.local hertz or yang_sun, nonlinear) the path is
//    that of the nonlinear kinematics below, on the linear problem;
//  * nonlinear, contact.solver kinsol: continuation/ natural (the depth grid, hit exactly) or
//    pseudo_arclength (to depth_max, through limit points), with the KINSOL corrector on the
//    Fischer-Burmeister system, events located (force extrema, inflections of T_N against k11
//    and k22 - the paper's critical force -, limit points of the depth, contact-set changes);
//  * nonlinear, contact.solver active_set: the primal-dual active-set method at each depth of the
//    grid (the cross-check solver, active_set_solver.hpp).
// The depth grid is path.depths, or 0, step, 2 step, ..., depth_max.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "analysis/indentation_problem.hpp"
#include "analysis/shell_model.hpp"
#include "continuation/branch.hpp"
#include "continuation/settings.hpp"
#include "io/case_file.hpp"

namespace si {

// Model, indenter and contact problem of a case, kept together (the problem refers to both).
struct IndentationSetup {
  CaseFile case_file;
  ShellModel model;
  IndenterPose pose;
  std::unique_ptr<Indenter> indenter;
  std::unique_ptr<IndentationProblem> problem;

  // Throws an input error naming the case file and key for a case that cannot run.
  // linear_solver: the contact Jacobian's solver, "cholesky_gmres" (indentation_problem.hpp) or a
  // sparse LU, "umfpack" or "klu" (docs/performance.md).
  IndentationSetup(CaseFile c, int threads,
                   const std::string& linear_solver = kPreconditionedKrylov);
};

// The indenter's pose: the case's indenter.position/direction/axis; without a position, the
// reference point starts on the apex's line of travel, clear of the shell.
IndenterPose default_indenter_pose(const CaseFile& c, const ShellModel& model);

struct PathPoint {
  int index = 0;  // position on the path (0 = the start point)
  IndentationState state;
  int iterations = 0;  // corrector (Newton / active-set) iterations that produced the point
  double step = 0;     // step that produced it (depth for grids, arclength for pseudo_arclength)
  double work = 0;     // indenter work so far, trapezoidal integral of force over depth, N mm
  // d(monitor)/d(depth) along the branch, one per PathResult::monitor_names (continuation runs;
  // NaN where the branch is nearly vertical in depth, at a fold); empty where unknown.
  Eigen::VectorXd depth_slopes;
};

// A point's scalar results in the order of path.csv's columns (io/path_results.hpp, docs/
// results.md): depth, force, reaction, apex deflection, contact radius, area, nodes, k11, k12,
// k22, energy, work, min gap, min multiplier, max complementarity, iterations, step, local
// indentation, local energy. The inverse
// restores those fields (checkpoints); the per-node vectors of the state stay empty.
std::vector<double> path_point_values(const PathPoint& p);
PathPoint path_point_from_values(const std::vector<double>& v);

struct PathResult {
  std::string method;  // "linear fast path", "natural", "pseudo_arclength", "active_set"
  std::vector<PathPoint> points;
  std::vector<cont::Event> events;
  std::vector<std::string> monitor_names;
  bool completed = false;  // reached the end of the path
  std::string status;      // e.g. "completed", "reached_bound", "step_too_small", "stopped"
  std::string reason;      // why it stopped early; empty when completed
};

// Called after each accepted point with the point and the problem's unknowns; returning false
// stops the run (status "stopped", every converged point kept).
using PathCallback = std::function<bool(const PathPoint&, const cont::Vector& z)>;

// Checkpoints and resume (continuation methods only; the linear fast path and the active-set
// grid are not resumable - they are fast or independent per depth and simply rerun).
struct PathControl {
  // The continuation library's checkpoint file, written every checkpoint_interval points and at
  // the end; beside it, "<checkpoint>.path.json" keeps the candidate set and the points. Empty:
  // no checkpoints.
  std::string checkpoint;
  int checkpoint_interval = 10;
  // Continue from `checkpoint` (same case): the points before it are kept, the path goes on
  // from its state and reproduces the uninterrupted run (to roundoff).
  bool resume = false;
};

// The Newton settings of a continuation run's corrector, for solves at a fixed depth outside a
// path (io/force_travel.hpp's warm starts).
cont::NewtonSettings path_newton_settings(const IndentationSetup& setup);

// The depth grid of a path section.
std::vector<double> depth_grid(const PathSpec& path);

// Runs the path. Numerical failures do not throw: they end the path with the reason.
PathResult run_indentation_path(IndentationSetup& setup, const PathCallback& callback = {},
                                const PathControl& control = {});

}  // namespace si
