// Stability events (docs/theory/continuation.md, "Stability events"): where the number of negative
// eigenvalues of the restricted tangent (Point::negative_eigenvalues) changes between two accepted
// points. A change from n_a to n_b means that the eigenvalues number min(n_a, n_b) + 1 ...
// max(n_a, n_b) (ascending, 1-based) crossed zero (Sylvester); each crossing is one event, located
// by Brent's method (event_location.hpp) on that eigenvalue, which is a continuous function along
// the branch (bisection on the count when fewer eigenpairs are computed, or when the computed
// eigenvalue does not change sign across the step). The located point is classified:
//   limit point   |dp/ds| at the event <= kFoldRatio max(|dp/ds| at A, at B): dp/ds vanishes with
//                 the eigenvalue (a simple fold: the critical mode is the branch's own tangent)
//   bifurcation   otherwise: the branch passes with dp/ds != 0 while J restricted is singular
// kFoldRatio = 1e-3: a fold located to the bracket width w has |dp/ds| ~ |p''| w, while its
// neighbours a step h away have ~ |p''| h, so the ratio is w/h << 1e-3; only a bifurcation within
// 1e-3 h of a fold would be misclassified. The event carries the crossing eigenvalue, its mode and
// the unit tangent at the event point (switch_branch starts from these).
#pragma once

#include "continuation/events.hpp"

namespace si::cont {

inline constexpr double kFoldRatio = 1e-3;

std::vector<Event> stability_events(const Indicator& indicator, const SegmentPoint& a,
                                    const SegmentPoint& b, const SegmentSolver& solve,
                                    const Settings& settings);

}  // namespace si::cont
