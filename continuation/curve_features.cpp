#include "continuation/curve_features.hpp"

#include <cmath>
#include <limits>

namespace si::cont {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

double at_or_nan(const Vector& v, int i) {
  return i >= 0 && i < v.size() ? v(i) : kNan;
}

// Value, first and second derivative along s, the latter's error, and the range of one
// coordinate of the curve: a monitor, or p for index -1.
struct Coordinate {
  double d1 = kNan;
  double d2 = kNan;
  double d2_error = kNan;
  double range = 0.0;
};

Coordinate coordinate(const Point& pt, int index, const CurveScales& scales) {
  if (index < 0)
    return {pt.tangent_p, pt.parameter_curvature, pt.parameter_curvature_error, scales.p_range()};
  return {at_or_nan(pt.monitor_slopes, index), at_or_nan(pt.monitor_curvatures, index),
          at_or_nan(pt.monitor_curvature_errors, index), scales.monitor_range(index)};
}

int sign(double v) {
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

struct Sample {
  double sigma = 0.0;
  TangentPoint point;
  int sign = 0;
  SegmentPoint at() const { return {sigma, point}; }
};

// Slope extremum (b = p): d2m/dp2 = g / (dp/ds)^3 goes from + to - at a maximum of dm/dp.
EventType feature_type(const Indicator& ind, const Point& before, const CurveScales& scales) {
  if (ind.type == EventType::kInflection) return EventType::kInflection;
  const double g = feature_value(ind, before, scales).g;
  return g * before.tangent_p > 0.0 ? EventType::kSlopeMax : EventType::kSlopeMin;
}

}  // namespace

FeatureValue feature_value(const Indicator& ind, const Point& pt, const CurveScales& scales) {
  const Coordinate a = coordinate(pt, ind.monitor, scales);
  const Coordinate b =
      coordinate(pt, ind.type == EventType::kInflection ? ind.against : -1, scales);
  FeatureValue v;
  v.g = a.d2 * b.d1 - a.d1 * b.d2;
  v.error = std::abs(a.d2_error * b.d1) + std::abs(a.d1 * b.d2_error);
  if (!(a.range > 0.0) || !(b.range > 0.0)) {
    v.curvature = 0.0;  // a constant coordinate: no curve to speak of
    return v;
  }
  const double speed = std::hypot(a.d1 / a.range, b.d1 / b.range);
  v.curvature = v.g / (a.range * b.range * speed * speed * speed);
  return v;
}

int resolved_sign(const FeatureValue& v, const Settings& settings) {
  if (!std::isfinite(v.g) || !std::isfinite(v.error) || !std::isfinite(v.curvature)) return 0;
  if (std::abs(v.g) <= settings.feature_noise_factor * v.error) return 0;
  if (std::abs(v.curvature) <= settings.feature_curvature_tolerance) return 0;
  return sign(v.g);
}

std::vector<Event> feature_events(const Indicator& ind, const std::vector<std::string>& names,
                                  const SegmentPoint& a, const SegmentPoint& b,
                                  const SegmentSolver& solve, const Settings& settings,
                                  const CurveScales& scales) {
  const auto signed_at = [&](const TangentPoint& tp) {
    return resolved_sign(feature_value(ind, tp.point, scales), settings);
  };
  const int sa = signed_at(a.point);
  const int sb = signed_at(b.point);
  if (sa == 0 || sb == 0 || sa == sb) return {};

  // Rule 3: the step's sub-intervals, interior points re-solved.
  const int parts = settings.feature_refinement;
  std::vector<Sample> samples{{a.sigma, a.point, sa}};
  for (int i = 1; i < parts; ++i) {
    Sample s;
    s.sigma = a.sigma + (b.sigma - a.sigma) * i / parts;
    s.sign = solve(s.sigma, nullptr, s.point) ? signed_at(s.point) : 0;
    samples.push_back(std::move(s));
  }
  samples.push_back({b.sigma, b.point, sb});

  std::vector<Event> events;
  const auto g = [&ind, &scales](const TangentPoint& tp) {
    return feature_value(ind, tp.point, scales).g;
  };
  for (std::size_t i = 0; i + 1 < samples.size(); ++i) {
    const Sample& lo = samples[i];
    const Sample& hi = samples[i + 1];
    if (lo.sign == 0 || hi.sign == 0 || lo.sign == hi.sign) continue;
    if (lo.point.point.signature != hi.point.point.signature) continue;  // rule 4
    TangentPoint at;
    bool located = false;
    const double accuracy = locate_root(g, lo.at(), hi.at(), solve, settings, at, located);
    Event event = event_at(feature_type(ind, lo.point.point, scales), ind, names, at);
    event.located = located;
    event.accuracy = accuracy;
    events.push_back(std::move(event));
  }
  return events;
}

}  // namespace si::cont
