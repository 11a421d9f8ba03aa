#include "continuation/events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "continuation/curve_features.hpp"
#include "continuation/stability_events.hpp"

namespace si::cont {
namespace {

int sign(double v) {
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

int find_monitor(const std::vector<std::string>& names, const std::string& name,
                 const std::string& field) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("continuation." + field + ": unknown monitor '" + name +
                              "' (known: " + (known.empty() ? "none" : known) + ")");
}

double value_or_nan(const Vector& v, int i) {
  return i >= 0 && i < v.size() ? v(i) : std::numeric_limits<double>::quiet_NaN();
}

// The simple continuous indicators' value at a point (NaN when unavailable).
double continuous_value(const Indicator& ind, const Point& pt) {
  switch (ind.type) {
    case EventType::kLimitPoint:
      return pt.tangent_p;
    case EventType::kZeroCrossing:
      return value_or_nan(pt.monitors, ind.monitor) - ind.level;
    case EventType::kMonitorMax:
    case EventType::kMonitorMin:
      return value_or_nan(pt.monitor_slopes, ind.monitor);
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

bool is_discrete(EventType type) {
  return type == EventType::kSignatureChange || type == EventType::kBifurcation;
}

bool is_feature(EventType type) {
  return type == EventType::kInflection || type == EventType::kSlopeMax;
}

// The discrete indicator's class at a point, as a vector compared for equality.
std::vector<int> discrete_value(const Indicator& ind, const Point& pt) {
  if (ind.type == EventType::kSignatureChange) return pt.signature;
  return {pt.jacobian_sign * sign(pt.tangent_p)};
}

bool changes(const Indicator& ind, const Point& a, const Point& b) {
  if (is_discrete(ind.type)) {
    if (ind.type == EventType::kBifurcation && (a.jacobian_sign == 0 || b.jacobian_sign == 0))
      return false;
    return discrete_value(ind, a) != discrete_value(ind, b);
  }
  const double ga = continuous_value(ind, a);
  const double gb = continuous_value(ind, b);
  if (std::isnan(ga) || std::isnan(gb)) return false;
  return sign(ga) != 0 && sign(gb) != sign(ga);  // a root exactly at a counts once, at b
}

EventType resolved_type(const Indicator& ind, const Point& a) {
  if (ind.type != EventType::kMonitorMax) return ind.type;
  return continuous_value(ind, a) > 0.0 ? EventType::kMonitorMax : EventType::kMonitorMin;
}

// The simple indicators (limit points, extrema, zeros, signature, bifurcation): one event per
// sign change, located on the whole step.
std::vector<Event> simple_events(const Indicator& ind, const std::vector<std::string>& names,
                                 const SegmentPoint& a, const SegmentPoint& b,
                                 const SegmentSolver& solve, const Settings& settings) {
  if (!changes(ind, a.point.point, b.point.point)) return {};
  TangentPoint at = b.point;
  bool located = false;
  double accuracy = b.sigma;
  if (is_discrete(ind.type)) {
    if (ind.type != EventType::kSignatureChange || settings.locate_signature_changes) {
      const auto value = [&ind](const TangentPoint& tp) { return discrete_value(ind, tp.point); };
      accuracy = locate_change(value, a, b, solve, settings, at, located);
    }
  } else {
    const auto g = [&ind](const TangentPoint& tp) { return continuous_value(ind, tp.point); };
    accuracy = locate_root(g, a, b, solve, settings, at, located, ind.value_tolerance);
  }
  Event event = event_at(resolved_type(ind, a.point.point), ind, names, at);
  event.located = located;
  event.accuracy = accuracy;
  return {event};
}

}  // namespace

std::vector<Indicator> make_indicators(const Settings& settings,
                                       const std::vector<std::string>& monitor_names) {
  std::vector<Indicator> out;
  if (settings.detect_limit_points) out.push_back({EventType::kLimitPoint, -1, -1});
  for (const auto& name : settings.extremum_monitors)
    out.push_back(
        {EventType::kMonitorMax, find_monitor(monitor_names, name, "extremum_monitors"), -1});
  for (const auto& name : settings.zero_crossing_monitors)
    out.push_back({EventType::kZeroCrossing,
                   find_monitor(monitor_names, name, "zero_crossing_monitors"), -1});
  for (const auto& crossing : settings.level_crossings)
    out.push_back({EventType::kZeroCrossing,
                   find_monitor(monitor_names, crossing.monitor, "level_crossings"), -1,
                   crossing.level, crossing.value_tolerance});
  for (const auto& pair : settings.inflections)
    out.push_back({EventType::kInflection, find_monitor(monitor_names, pair.monitor, "inflections"),
                   find_monitor(monitor_names, pair.against, "inflections")});
  for (const auto& name : settings.slope_extremum_monitors)
    out.push_back(
        {EventType::kSlopeMax, find_monitor(monitor_names, name, "slope_extremum_monitors"), -1});
  if (settings.detect_signature_changes) out.push_back({EventType::kSignatureChange, -1, -1});
  if (settings.detect_bifurcations) out.push_back({EventType::kBifurcation, -1, -1});
  if (settings.stability_modes > 0) out.push_back({EventType::kStabilityChange, -1, -1});
  return out;
}

AnalysisNeeds analysis_needs(const std::vector<Indicator>& indicators, const Settings& settings,
                             const std::vector<std::string>& monitor_names) {
  AnalysisNeeds needs;
  std::vector<int>& which = needs.derivative_monitors;
  for (const auto& ind : indicators) {
    const bool derivatives = ind.type == EventType::kMonitorMax || is_feature(ind.type);
    needs.slopes |= derivatives;
    needs.curvatures |= is_feature(ind.type);
    needs.curvature_errors |= is_feature(ind.type);
    // The feature detector refuses sign changes across a signature change.
    needs.signature |= ind.type == EventType::kSignatureChange || is_feature(ind.type);
    if (derivatives)
      for (int m : {ind.monitor, ind.against})
        if (m >= 0) which.push_back(m);
  }
  for (const auto& name : settings.slope_monitors)
    which.push_back(find_monitor(monitor_names, name, "slope_monitors"));
  needs.slopes |= !settings.slope_monitors.empty();
  std::sort(which.begin(), which.end());
  which.erase(std::unique(which.begin(), which.end()), which.end());
  needs.stability_modes = settings.stability_modes;
  return needs;
}

void CurveScales::include(const Point& point) {
  if (empty || low.size() != point.monitors.size()) {
    low = high = point.monitors;
    p_low = p_high = point.p;
    empty = false;
    return;
  }
  low = low.cwiseMin(point.monitors);
  high = high.cwiseMax(point.monitors);
  p_low = std::min(p_low, point.p);
  p_high = std::max(p_high, point.p);
}

double CurveScales::monitor_range(int i) const {
  return (empty || i < 0 || i >= low.size()) ? 0.0 : high(i) - low(i);
}

Event event_at(EventType type, const Indicator& indicator,
               const std::vector<std::string>& monitor_names, const TangentPoint& at) {
  Event event;
  event.type = type;
  event.name = event_type_name(type);
  if (indicator.monitor >= 0) event.monitor = monitor_names[indicator.monitor];
  if (indicator.against >= 0) event.against = monitor_names[indicator.against];
  event.p = at.point.p;
  event.x = at.point.x;
  event.monitors = at.point.monitors;
  event.branch_id = at.point.branch_id;
  return event;
}

std::vector<Event> find_events(const std::vector<Indicator>& indicators,
                               const std::vector<std::string>& monitor_names, const TangentPoint& a,
                               const TangentPoint& b, double sigma_b, const SegmentSolvers& solve,
                               const Settings& settings, int step, BorderedSolver& metric,
                               const CurveScales& scales) {
  const SegmentPoint start{0.0, a};
  const SegmentPoint end{sigma_b, b};
  std::vector<Event> events;
  for (const auto& ind : indicators) {
    std::vector<Event> found;
    if (ind.type == EventType::kStabilityChange)
      found = stability_events(ind, start, end, solve.with_stability, settings);
    else if (is_feature(ind.type))
      found = feature_events(ind, monitor_names, start, end, solve.plain, settings, scales);
    else if (ind.type == EventType::kZeroCrossing)
      found = simple_events(ind, monitor_names, start, end, solve.monitors_only, settings);
    else
      found = simple_events(ind, monitor_names, start, end, solve.plain, settings);
    for (auto& event : found) {
      event.step = step;
      const Vector dx = event.x - a.point.x;
      const double dp = event.p - a.point.p;
      event.arclength = a.point.arclength + std::sqrt(metric.inner(dx, dp, dx, dp));
      events.push_back(std::move(event));
    }
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& l, const Event& r) { return l.arclength < r.arclength; });
  return events;
}

}  // namespace si::cont
