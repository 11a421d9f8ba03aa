#include "continuation/event_location.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace si::cont {
namespace {

int sign(double v) {
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

// A point at sigma; if it cannot be had (the interpolation lands exactly on a root where J is
// singular, e.g. a bifurcation whose indicator is linear), a point slightly off it towards the
// bracket's middle, then the middle itself. sigma is set to where the point was found.
bool solve_near(const SegmentSolver& solve, double& sigma, double middle, const SegmentChord* chord,
                TangentPoint& out) {
  if (solve(sigma, chord, out)) return true;
  for (const double other : {sigma + 1e-3 * (middle - sigma), middle}) {
    if (other == sigma) continue;
    if (solve(other, chord, out)) {
      sigma = other;
      return true;
    }
  }
  return false;
}

// One end of the bracket: its local coordinate, the indicator's value and the solved point.
struct Sample {
  double sigma;
  double g;
  TangentPoint point;
};

// Brent's step from the best end b towards the root (Brent 1973, ch. 4): inverse quadratic
// interpolation through a (the previous b), b and c (the bracket's other end) when the three values
// differ, else the secant through a and b; nullopt when the interpolated step is not accepted
// (it leaves the bracket's inner three quarters, or is more than half the step before last: the
// interpolation is not converging): then the caller bisects.
std::optional<double> interpolated_step(const Sample& a, const Sample& b, const Sample& c,
                                        double half_width, double previous_step, double tolerance) {
  const double s = b.g / a.g;
  double p = 0.0, q = 0.0;
  if (a.sigma == c.sigma) {
    p = 2.0 * half_width * s;
    q = 1.0 - s;
  } else {
    const double qa = a.g / c.g, r = b.g / c.g;
    p = s * (2.0 * half_width * qa * (qa - r) - (b.sigma - a.sigma) * (r - 1.0));
    q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
  }
  if (p > 0.0) q = -q;
  p = std::abs(p);
  if (2.0 * p <
      std::min(3.0 * half_width * q - std::abs(tolerance * q), std::abs(previous_step * q)))
    return p / q;
  return std::nullopt;
}

}  // namespace

double locate_root(const std::function<double(const TangentPoint&)>& g, const SegmentPoint& lo,
                   const SegmentPoint& hi, const SegmentSolver& solve, const Settings& settings,
                   TangentPoint& out, bool& located, double value_tolerance) {
  // Brent's method: b the best estimate, c the bracket's other end (g(c) of the other sign), a
  // the previous b; d the last step, e the one before.
  Sample a{lo.sigma, g(lo.point), lo.point};
  Sample b{hi.sigma, g(hi.point), hi.point};
  Sample c = b;
  double d = b.sigma - a.sigma, e = d;
  const double tolerance = 0.5 * settings.event_tolerance;
  const auto small_enough = [value_tolerance](const Sample& x) {
    return x.g == 0.0 || std::abs(x.g) <= value_tolerance;
  };
  for (int it = 0; it < settings.event_max_iterations; ++it) {
    if (sign(b.g) == sign(c.g)) {  // the root lies between a and b
      c = a;
      d = e = b.sigma - a.sigma;
    }
    if (std::abs(c.g) < std::abs(b.g)) {  // b: the end nearer the root, a the previous b
      std::swap(b, c);
      a = c;
    }
    const double half_width = 0.5 * (c.sigma - b.sigma);
    if (std::abs(half_width) <= tolerance || small_enough(b)) break;
    const std::optional<double> step = std::abs(e) >= tolerance && std::abs(a.g) > std::abs(b.g)
                                           ? interpolated_step(a, b, c, half_width, e, tolerance)
                                           : std::nullopt;
    e = step ? d : half_width;
    d = step ? *step : half_width;
    double sigma = b.sigma + (std::abs(d) > tolerance ? d : std::copysign(tolerance, half_width));
    const bool b_first = b.sigma < c.sigma;
    const Sample& left = b_first ? b : c;
    const Sample& right = b_first ? c : b;
    const SegmentChord chord{left.sigma, left.point.point, right.sigma, right.point.point};
    TangentPoint trial;
    if (!solve_near(solve, sigma, b.sigma + half_width, &chord, trial)) break;
    const double value = g(trial);
    if (std::isnan(value)) break;
    a = std::move(b);
    b = {sigma, value, std::move(trial)};
  }
  out = b.point;
  const double width = b.g == 0.0 ? 0.0 : std::abs(c.sigma - b.sigma);
  if (width > settings.event_tolerance && small_enough(b)) {
    located = true;
    return std::min(width, std::abs(b.g) * width / std::abs(c.g - b.g));
  }
  located = width <= settings.event_tolerance;
  return width;
}

double locate_change(const std::function<std::vector<int>(const TangentPoint&)>& value,
                     const SegmentPoint& a, const SegmentPoint& b, const SegmentSolver& solve,
                     const Settings& settings, TangentPoint& out, bool& located) {
  const std::vector<int> start = value(a.point);
  double lo = a.sigma;
  double hi = b.sigma;
  TangentPoint lo_point = a.point;
  out = b.point;
  located = false;
  for (int it = 0; it < settings.event_max_iterations; ++it) {
    if (hi - lo <= settings.event_tolerance) break;
    const double mid = 0.5 * (lo + hi);
    const SegmentChord chord{lo, lo_point.point, hi, out.point};
    TangentPoint trial;
    if (!solve(mid, &chord, trial)) return hi - lo;
    if (value(trial) == start) {
      lo = mid;
      lo_point = std::move(trial);
    } else {
      hi = mid;
      out = std::move(trial);
    }
  }
  located = hi - lo <= settings.event_tolerance;
  return hi - lo;
}

}  // namespace si::cont
