// Locating an event on the segment between two accepted points (docs/theory/continuation.md,
// "Events"): points on the segment are re-solved at local coordinates sigma by a SegmentSolver;
// continuous indicators by the Illinois variant of regula falsi with a bisection safeguard,
// discrete ones by bisection, until the bracket is at most Settings::event_tolerance wide.
#pragma once

#include <functional>
#include <vector>

#include "continuation/point_analysis.hpp"
#include "continuation/settings.hpp"

namespace si::cont {

// Puts a converged, analysed point on the current segment at local coordinate sigma.
using SegmentSolver = std::function<bool(double sigma, TangentPoint& out)>;

// A point of the segment with its local coordinate (a view: the point is not copied, so that
// steps without events cost no copy of x).
struct SegmentPoint {
  double sigma;
  const TangentPoint& point;
};

// The root of the continuous function g between lo and hi (lo.sigma < hi.sigma, g(lo) and g(hi)
// of opposite signs); `out` receives the bracket end with the smaller |g|. Returns the final
// bracket width (0 if g hit exactly 0); `located` is set when it is <= event_tolerance.
double locate_root(const std::function<double(const TangentPoint&)>& g, const SegmentPoint& lo,
                   const SegmentPoint& hi, const SegmentSolver& solve, const Settings& settings,
                   TangentPoint& out, bool& located);

// Bisection for the first change of the discrete value `value` between lo and hi; `out` receives
// the first point found with a value other than lo's (hi if none). Returns the final width.
double locate_change(const std::function<std::vector<int>(const TangentPoint&)>& value,
                     const SegmentPoint& lo, const SegmentPoint& hi, const SegmentSolver& solve,
                     const Settings& settings, TangentPoint& out, bool& located);

}  // namespace si::cont
