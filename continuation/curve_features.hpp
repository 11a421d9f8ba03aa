// The curve-feature detector: inflections of a monitor a against a monitor b (sign changes of
// d2a/db2) and extrema of a monitor's slope dm/dp (b = p; for a force monitor, slope_min is the
// minimum tangent stiffness), reported only when resolved (docs/theory/continuation.md, "Curve
// features"). The indicator is g = a'' b' - a' b'' (= b'^3 d2a/db2), derivatives along s.
//
// Rules, each against a way the raw sign change cries wolf:
//  1. Noise: g's error estimate e = |a''_err b'| + |a' b''_err| (point_analysis.hpp: the second
//     derivatives at two difference steps). A point's g has a sign only if |g| > noise_factor e:
//     inside an exactly linear segment g is roundoff and has none.
//  2. Scale: the curvature of the curve in its own scale, kappa = g / (A B v^3), v^2 =
//     (a'/A)^2 + (b'/B)^2, with A and B the ranges of a and b over the branch so far (a
//     dimensionless curvature: 1 = a radius as large as the curve), must exceed
//     curvature_tolerance in magnitude: a straight segment's 1e-12 wiggles are not features.
//  3. Confirmation: a sign change between two accepted points, both signed, is re-examined on
//     `refinement` equal sub-intervals of the step (each interior point re-solved); a feature is
//     reported in each sub-interval whose ends are both signed, with opposite signs and the same
//     Problem::signature(), located there by regula falsi on g.
//  4. Kinks: a sign change across a signature change (e.g. a node entering contact: a kink of the
//     curve, where one-sided derivatives jump) is never a feature: it is the signature event.
// Consequences: a feature closer than a sub-interval to a kink, or whose bracketing points are
// unsigned (within the noise or the straight tolerance), is not reported; "none" is a valid
// answer. Two features within one step that cancel in sign are not seen.
#pragma once

#include "continuation/events.hpp"

namespace si::cont {

struct FeatureValue {
  double g = 0.0;          // the raw indicator
  double error = 0.0;      // its error estimate (rule 1)
  double curvature = 0.0;  // kappa of rule 2
};

FeatureValue feature_value(const Indicator& indicator, const Point& point,
                           const CurveScales& scales);

// +1 / -1, or 0 when rule 1 or 2 leaves the point without a sign.
int resolved_sign(const FeatureValue& value, const Settings& settings);

std::vector<Event> feature_events(const Indicator& indicator,
                                  const std::vector<std::string>& monitor_names,
                                  const SegmentPoint& a, const SegmentPoint& b,
                                  const SegmentSolver& solve, const Settings& settings,
                                  const CurveScales& scales);

}  // namespace si::cont
