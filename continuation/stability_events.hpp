// Stability events (docs/theory/continuation.md, "Stability events"): where the number of negative
// eigenvalues of the restricted tangent (Point::negative_eigenvalues) changes between two accepted
// points. A change from n_a to n_b means that the eigenvalues number min(n_a, n_b) + 1 ...
// max(n_a, n_b) (ascending, 1-based) crossed zero (Sylvester); each crossing is one event, located
// by Brent's method (event_location.hpp) on that eigenvalue, which is a continuous function along
// the branch (bisection on the count when fewer eigenpairs are computed, or when the computed
// eigenvalue does not change sign across the step). The located point is classified:
//   limit point   dp/ds has opposite signs at A and B: the parameter turns back within the step,
//                 and dp/ds vanishes with the eigenvalue (a simple fold: the critical mode is the
//                 branch's own tangent)
//   bifurcation   otherwise: the branch passes with dp/ds != 0 while J restricted is singular
// The sign test at the step's ends, not |dp/ds| at the event: at a bifurcation the bordered matrix
// is singular as well, and the tangent solved at the located point is an arbitrary mix of the two
// branches' (the hinged roof's second bifurcation under load control came out as a "limit point"
// with step 0.25 mm and as a bifurcation with 0.5 mm that way). Only a fold and a bifurcation
// within one step would be misclassified. The event carries the crossing eigenvalue, its mode and
// the unit tangent at the event point (switch_branch starts from these).
#pragma once

#include "continuation/events.hpp"

namespace si::cont {

std::vector<Event> stability_events(const Indicator& indicator, const SegmentPoint& a,
                                    const SegmentPoint& b, const SegmentSolver& solve,
                                    const Settings& settings);

}  // namespace si::cont
