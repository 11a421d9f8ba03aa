// Resolved sign changes of a curve-feature indicator on the converged points of a path (the
// paper's critical force, critical_force.hpp; the inflections of T(h), critical_points.hpp):
// the library's rules (continuation/curve_features.hpp) applied to derivatives in the depth
// taken on the points, not to located re-solves:
//  1. noise: a point's indicator has a sign only outside its error estimate (the solves'
//     accuracy carried through the divided differences) - inside an exactly linear segment it
//     is roundoff and has none;
//  2. scale: the curve's curvature in its own scale must exceed the library's tolerance;
//  4. kinks: a stencil across a change of the contact set (one-sided derivatives jump there) has
//     no sign; a sign change counts only between two signed points with every stencil between
//     them on one contact set.
// Rule 3 (confirmation by re-solving inside the step) is not applied: a feature is not located
// (accuracy = the depth bracket of its two signed points). Points restored from a checkpoint
// carry no contact set and no sign.
#pragma once

#include <functional>
#include <vector>

#include "analysis/indentation_run.hpp"
#include "continuation/events.hpp"

namespace si {

// The nodes pressing at a point (multiplier above 1e-9 of the largest); empty for a point
// restored from values (no per-node vectors).
std::vector<int> pressing_nodes(const IndentationState& state);

// The relative accuracy of a point's values and slopes (the fast path's direct solve, the active
// set's and KINSOL's 1e-10 tolerances), per unit of the quantity's largest magnitude.
constexpr double kPointAccuracy = 1e-9;

// The curve at interior point i (0 < i < n - 1) as the library's Point (p = depth, tangent_p
// = 1): its monitors' first and second derivatives in the depth and the latter's error.
using GridPoint = std::function<cont::Point(int i)>;

// The sign changes of `indicator` between the points, in depth order: events of type
// kInflection (an inflection indicator) or kSlopeMax / kSlopeMin (a slope extremum: the sign of
// d2m/dh2 going from + to - / - to +), with p, step (the later signed point), accuracy and
// monitors (the run's monitors, interpolated linearly at p); located false; names unset.
// `scales`: the curve's extent over the points.
std::vector<cont::Event> grid_features(const std::vector<PathPoint>& points,
                                       const cont::Indicator& indicator, const GridPoint& at,
                                       const cont::CurveScales& scales);

// Three-point divided-difference weights on the uneven grid h_{i-1}, h_i, h_{i+1} (second order):
// the first derivative (w1) and the second (w2) at the middle point.
struct DifferenceWeights {
  Eigen::Vector3d first;
  Eigen::Vector3d second;
};
DifferenceWeights difference_weights(double h1, double h2);

}  // namespace si
