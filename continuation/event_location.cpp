#include "continuation/event_location.hpp"

#include <cmath>

namespace si::cont {
namespace {

int sign(double v) {
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}

// A point at sigma; if it cannot be had (regula falsi lands exactly on a root where J is singular,
// e.g. a bifurcation whose indicator is linear), a point slightly off it towards the bracket's
// middle, then the middle itself.
// sigma is set to where the point was found.
bool solve_near(const SegmentSolver& solve, double& sigma, double middle, TangentPoint& out) {
  if (solve(sigma, out)) return true;
  for (const double other : {sigma + 1e-3 * (middle - sigma), middle}) {
    if (other == sigma) continue;
    if (solve(other, out)) {
      sigma = other;
      return true;
    }
  }
  return false;
}

}  // namespace

double locate_root(const std::function<double(const TangentPoint&)>& g, const SegmentPoint& a,
                   const SegmentPoint& b, const SegmentSolver& solve, const Settings& settings,
                   TangentPoint& out, bool& located) {
  struct End {
    double sigma;
    double g;       // true value
    double weight;  // Illinois: the stale end's value is halved
    TangentPoint point;
  };
  const double ga = g(a.point);
  const double gb = g(b.point);
  End lo{a.sigma, ga, ga, a.point};
  End hi{b.sigma, gb, gb, b.point};
  int last_replaced = 0;  // +1: lo, -1: hi (Illinois halves the end kept twice)
  double width_before = b.sigma - a.sigma;
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
    if (!solve_near(solve, sigma, 0.5 * (lo.sigma + hi.sigma), trial)) break;
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

double locate_change(const std::function<std::vector<int>(const TangentPoint&)>& value,
                     const SegmentPoint& a, const SegmentPoint& b, const SegmentSolver& solve,
                     const Settings& settings, TangentPoint& out, bool& located) {
  const std::vector<int> start = value(a.point);
  double lo = a.sigma;
  double hi = b.sigma;
  out = b.point;
  located = false;
  for (int it = 0; it < settings.event_max_iterations; ++it) {
    if (hi - lo <= settings.event_tolerance) break;
    const double mid = 0.5 * (lo + hi);
    TangentPoint trial;
    if (!solve(mid, trial)) return hi - lo;
    if (value(trial) == start) {
      lo = mid;
    } else {
      hi = mid;
      out = trial;
    }
  }
  located = hi - lo <= settings.event_tolerance;
  return hi - lo;
}

}  // namespace si::cont
