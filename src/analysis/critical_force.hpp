// The paper's critical contact force (P12, Figs 10-11): the inflection point of T_N plotted
// against an apex curvature (k11 or k22), found on the converged points of a path.
//
// Why not the continuation library's located inflection events: d2 T / dk2 jumps wherever the
// contact set changes (a node enters contact), so along an indentation path it changes sign at
// many contact changes; locating each by bisection costs dozens of corrector solves and reports
// noise. Here the second derivative is the three-point divided difference on the path's points,
// and an inflection is reported only where its sign changes and then stays changed for
// `persistence` consecutive points on each side (3 by default: on the paper cap a persistence of 2
// still reported contact-change wiggles of T_N against k11 as inflections). The depth and force are
// interpolated linearly between the two points that bracket the change; the accuracy is the
// bracket's depth width.
#pragma once

#include <string>
#include <vector>

#include "analysis/indentation_run.hpp"

namespace si {

// curvature: 0 = k11, 1 = k12 + k21, 2 = k22 (IndentationState::apex_curvature).
std::vector<cont::Event> critical_force_events(const std::vector<PathPoint>& points, int curvature,
                                               int persistence = 3);

}  // namespace si
