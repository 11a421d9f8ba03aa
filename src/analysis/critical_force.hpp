// The paper's critical contact force (P12, Figs 10-11): the inflection of T_N plotted against an
// apex curvature (k11 or k22), reported only where it is resolved (docs/theory/continuation.md,
// "Curve features"; issue 15: the raw sign changes of d2T/dk2 sit on the kinks where nodes enter
// contact and inside exactly linear segments, and were reported as critical forces).
//
// Found on the path's converged points (every method), with the library's curve-feature rules
// (cont::feature_value, cont::resolved_sign) and derivatives in the depth by three-point divided
// differences; the library's located inflections were 5.8 times the main job's time
// (indentation_run.cpp):
//  1. noise: the second differences' error from the solves' accuracy (1e-9 of the coordinate's
//     largest magnitude per point) - inside an exactly linear segment g is roundoff;
//  2. scale: the curvature of the (k, T) curve in its own scale (each coordinate over its range
//     on the path) must exceed 1e-3 (cont::Settings::feature_curvature_tolerance);
//  4. kinks: a stencil across a change of the contact set (a kink: one-sided derivatives jump)
//     has no sign; a sign change is an inflection only between two signed points whose stencils
//     share one contact set.
// Rule 3 (confirmation by re-solving inside the step) is not applied: an inflection is not
// located (accuracy = the bracket's depth width). Points restored from a checkpoint carry no
// contact set and no sign (a resumed run reports none before its checkpoint). With linear
// kinematics T and k are linear in the depth on each contact set, so the linear path never has one:
// "none" is the answer, said plainly.
#pragma once

#include <string>
#include <vector>

#include "analysis/indentation_run.hpp"

namespace si {

// curvature: 0 = k11, 1 = k12 + k21, 2 = k22 (IndentationState::apex_curvature).
std::vector<cont::Event> critical_force_events(const std::vector<PathPoint>& points, int curvature);

}  // namespace si
