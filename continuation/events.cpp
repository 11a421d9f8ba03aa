#include "continuation/events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

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

// The continuous indicator's value at a point (NaN when unavailable).
double continuous_value(const Indicator& ind, const Point& pt) {
  switch (ind.type) {
    case EventType::kLimitPoint:
      return pt.tangent_p;
    case EventType::kZeroCrossing:
      return value_or_nan(pt.monitors, ind.monitor);
    case EventType::kMonitorMax:
    case EventType::kMonitorMin:
      return value_or_nan(pt.monitor_slopes, ind.monitor);
    case EventType::kInflection:
      return value_or_nan(pt.monitor_curvatures, ind.monitor) *
                 value_or_nan(pt.monitor_slopes, ind.against) -
             value_or_nan(pt.monitor_slopes, ind.monitor) *
                 value_or_nan(pt.monitor_curvatures, ind.against);
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

bool is_discrete(EventType type) {
  return type == EventType::kSignatureChange || type == EventType::kBifurcation;
}

// The discrete indicator's class at a point, as a vector compared for equality.
std::vector<int> discrete_value(const Indicator& ind, const Point& pt) {
  if (ind.type == EventType::kSignatureChange) return pt.signature;
  return {pt.jacobian_sign * sign(pt.tangent_p)};
}

// Bisection for the first change of a discrete indicator on (0, sigma_b).
double locate_change(const Indicator& ind, const TangentPoint& a, const TangentPoint& b,
                     double sigma_b, const SegmentSolver& solve, const Settings& settings,
                     TangentPoint& out, bool& located) {
  const std::vector<int> start = discrete_value(ind, a.point);
  double lo = 0.0;
  double hi = sigma_b;
  out = b;
  located = false;
  for (int it = 0; it < settings.event_max_iterations; ++it) {
    if (hi - lo <= settings.event_tolerance) break;
    const double mid = 0.5 * (lo + hi);
    TangentPoint trial;
    if (!solve(mid, trial)) return hi - lo;
    if (discrete_value(ind, trial.point) == start) {
      lo = mid;
    } else {
      hi = mid;
      out = trial;
    }
  }
  located = hi - lo <= settings.event_tolerance;
  return hi - lo;
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
  for (const auto& pair : settings.inflections)
    out.push_back({EventType::kInflection, find_monitor(monitor_names, pair.monitor, "inflections"),
                   find_monitor(monitor_names, pair.against, "inflections")});
  if (settings.detect_signature_changes) out.push_back({EventType::kSignatureChange, -1, -1});
  if (settings.detect_bifurcations) out.push_back({EventType::kBifurcation, -1, -1});
  return out;
}

AnalysisNeeds analysis_needs(const std::vector<Indicator>& indicators) {
  AnalysisNeeds needs;
  for (const auto& ind : indicators) {
    needs.slopes |= ind.type == EventType::kMonitorMax || ind.type == EventType::kInflection;
    needs.curvatures |= ind.type == EventType::kInflection;
    needs.signature |= ind.type == EventType::kSignatureChange;
  }
  return needs;
}

double locate_root(const std::function<double(const TangentPoint&)>& g, const TangentPoint& a,
                   const TangentPoint& b, double sigma_b, const SegmentSolver& solve,
                   const Settings& settings, TangentPoint& out, bool& located) {
  struct End {
    double sigma;
    double g;       // true value
    double weight;  // Illinois: the stale end's value is halved
    TangentPoint point;
  };
  End lo{0.0, g(a), g(a), a};
  End hi{sigma_b, g(b), g(b), b};
  int last_replaced = 0;  // +1: lo, -1: hi (Illinois halves the end kept twice)
  double width_before = sigma_b;
  for (int it = 0; it < settings.event_max_iterations; ++it) {
    const double width = hi.sigma - lo.sigma;
    if (width <= settings.event_tolerance || lo.g == 0.0 || hi.g == 0.0) break;
    // Regula falsi, with a bisection every third iteration that failed to halve the bracket.
    double sigma = lo.sigma - lo.weight * width / (hi.weight - lo.weight);
    if (it % 3 == 2) {
      if (width > 0.5 * width_before) sigma = 0.5 * (lo.sigma + hi.sigma);
      width_before = width;
    }
    if (!(sigma > lo.sigma && sigma < hi.sigma)) sigma = 0.5 * (lo.sigma + hi.sigma);
    TangentPoint trial;
    if (!solve(sigma, trial)) break;
    const double value = g(trial);
    if (std::isnan(value)) break;
    if (sign(value) == sign(lo.g)) {
      lo = {sigma, value, value, trial};
      if (last_replaced == 1) hi.weight *= 0.5;
      last_replaced = 1;
    } else {
      hi = {sigma, value, value, trial};
      if (last_replaced == -1) lo.weight *= 0.5;
      last_replaced = -1;
    }
  }
  const double width = (lo.g == 0.0 || hi.g == 0.0) ? 0.0 : hi.sigma - lo.sigma;
  located = width <= settings.event_tolerance;
  out = (std::abs(lo.g) < std::abs(hi.g)) ? lo.point : hi.point;
  return width;
}

std::vector<Event> find_events(const std::vector<Indicator>& indicators,
                               const std::vector<std::string>& monitor_names, const TangentPoint& a,
                               const TangentPoint& b, double sigma_b, const SegmentSolver& solve,
                               const Settings& settings, int step, BorderedSolver& metric) {
  std::vector<Event> events;
  for (const auto& ind : indicators) {
    if (!changes(ind, a.point, b.point)) continue;
    Event event;
    event.type = resolved_type(ind, a.point);
    event.name = event_type_name(event.type);
    if (ind.monitor >= 0) event.monitor = monitor_names[ind.monitor];
    if (ind.against >= 0) event.against = monitor_names[ind.against];
    TangentPoint at = b;
    if (is_discrete(ind.type)) {
      const bool locate =
          ind.type != EventType::kSignatureChange || settings.locate_signature_changes;
      event.accuracy =
          locate ? locate_change(ind, a, b, sigma_b, solve, settings, at, event.located) : sigma_b;
    } else {
      const auto g = [&ind](const TangentPoint& tp) { return continuous_value(ind, tp.point); };
      event.accuracy = locate_root(g, a, b, sigma_b, solve, settings, at, event.located);
    }
    event.p = at.point.p;
    event.x = at.point.x;
    event.monitors = at.point.monitors;
    event.step = step;
    const Vector dx = at.point.x - a.point.x;
    const double dp = at.point.p - a.point.p;
    event.arclength = a.point.arclength + std::sqrt(metric.inner(dx, dp, dx, dp));
    events.push_back(std::move(event));
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const Event& l, const Event& r) { return l.arclength < r.arclength; });
  return events;
}

}  // namespace si::cont
