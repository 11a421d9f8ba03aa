// Locating an event on the segment between two accepted points (docs/theory/continuation.md,
// "Events"): points on the segment are re-solved at local coordinates sigma by a SegmentSolver;
// continuous indicators by Brent's method (inverse quadratic interpolation, secant and bisection
// safeguard), discrete ones by bisection, until the bracket is at most Settings::event_tolerance
// wide.
#pragma once

#include <functional>
#include <vector>

#include "continuation/point_analysis.hpp"
#include "continuation/settings.hpp"

namespace si::cont {

// The solved points of the segment nearest a point to be solved, one on either side of it: its
// corrector starts from their chord. Event location passes its bracket's ends, which close in on
// the event, so that the corrector starts ever closer to the solution (one or two Newton
// iterations instead of three or four from the step's own chord).
struct SegmentChord {
  double sigma_lo;
  const Point& lo;
  double sigma_hi;
  const Point& hi;
};

// Puts a converged, analysed point on the current segment at local coordinate sigma, its
// corrector started from the chord (nullptr: the chord of the step's ends).
using SegmentSolver =
    std::function<bool(double sigma, const SegmentChord* chord, TangentPoint& out)>;

// A point of the segment with its local coordinate (a view: the point is not copied, so that
// steps without events cost no copy of x).
struct SegmentPoint {
  double sigma;
  const TangentPoint& point;
};

// The root of the continuous function g between lo and hi (lo.sigma < hi.sigma, g(lo) and g(hi)
// of opposite signs); `out` receives the bracket end with the smaller |g|. Returns the final
// bracket width (0 if g hit exactly 0); `located` is set when it is <= event_tolerance.
// With value_tolerance > 0 the search also stops once an end has |g| <= value_tolerance (the
// level crossings of a monitor known to that accuracy, e.g. a failure index to 1e-7): `located`
// is set and the returned accuracy is the distance to the root estimated from the bracket's secant,
// |g| / |dg/dsigma|. The interpolation brings the best end to the root superlinearly, while the
// bracket closes only by a last step just past it: the value test saves those corrector solves.
double locate_root(const std::function<double(const TangentPoint&)>& g, const SegmentPoint& lo,
                   const SegmentPoint& hi, const SegmentSolver& solve, const Settings& settings,
                   TangentPoint& out, bool& located, double value_tolerance = 0.0);

// Bisection for the first change of the discrete value `value` between lo and hi; `out` receives
// the first point found with a value other than lo's (hi if none). Returns the final width.
double locate_change(const std::function<std::vector<int>(const TangentPoint&)>& value,
                     const SegmentPoint& lo, const SegmentPoint& hi, const SegmentSolver& solve,
                     const Settings& settings, TangentPoint& out, bool& located);

}  // namespace si::cont
