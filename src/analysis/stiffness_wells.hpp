// The extrema of the tangent stiffness s = dT/dh that hold at the curve's own scale, across the
// kinks where nodes enter contact (issue 15 items 3 and 4; docs/theory/continuation.md 14).
//
// On a fine mesh a node enters contact between almost every pair of points, and s jumps up at
// each: the sign changes of d2T/dh2 that the curve-feature rules accept (one contact set on both
// sides) then vanish, although the converged curve has a stiffness minimum. Its definition at the
// curve's scale: a *well* of s is a run of consecutive points where s stays within `fraction` of
// its extreme value s_m (s <= s_m + fraction |s_m| for a minimum), bounded on both sides by points
// beyond it - the stiffness rises by the fraction on both sides (a path that ends inside the
// well has not shown the minimum). Its depth is the vertex of the least-squares parabola
// s ~ c0 + c1 x + c2 x^2 through the well's points: the jumps of the kinks are scatter about it,
// and shrink as the mesh is refined, so the vertex converges where a single sign change cannot.
// The vertex is reported only where the parabola's curvature has the well's sign and stands out
// of its own standard error (t >= kCurvatureSignificance) and the vertex lies among the well's
// points; its accuracy is twice the vertex's standard error (delta method) - a statement of the
// scatter, not a bracket.
#pragma once

#include <optional>
#include <vector>

#include "analysis/critical_point.hpp"

namespace si {

// The stiffness dT/dh (N/mm) at a depth (mm): the points' exact slopes, or the secants of the
// segments at their mid-depths where the points carry none.
struct StiffnessSample {
  double depth = 0;
  double stiffness = 0;
};

struct StiffnessWell {
  CriticalKind kind = CriticalKind::kStiffnessMin;  // or kStiffnessMax
  int first = 0;  // the well's samples: first ... last (inclusive)
  int last = 0;
  double from = 0;  // the bounding samples' depths (mm): the well lies strictly inside
  double to = 0;
};

// The wells of `samples` (in depth order) at the relative depth `fraction`, in depth order.
// Each extreme sample belongs to one well at most: a run holding a lower minimum (higher
// maximum) is that one's well.
std::vector<StiffnessWell> stiffness_wells(const std::vector<StiffnessSample>& samples,
                                           double fraction);

struct StiffnessVertex {
  double depth = 0;      // mm
  double stiffness = 0;  // N/mm, the parabola's value at its vertex
  double accuracy = 0;   // mm, twice the vertex's standard error
};

// The parabola's vertex over the well's samples; none where fewer than 5 samples, the curvature
// has the wrong sign or is not significant, or the vertex lies outside the well's samples.
std::optional<StiffnessVertex> fitted_vertex(const std::vector<StiffnessSample>& samples,
                                             const StiffnessWell& well);

// The curvature's t-value a vertex needs: the jumps at the kinks are not independent noise, so
// a generous margin over the 95 % point of a t-distribution (about 2).
constexpr double kCurvatureSignificance = 3.0;

}  // namespace si
