#include "continuation/event_location.hpp"

#include <algorithm>
#include <utility>

#include "continuation/brent_root.hpp"

namespace si::cont {
namespace {

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

}  // namespace

double locate_root(const std::function<double(const TangentPoint&)>& g, const SegmentPoint& lo,
                   const SegmentPoint& hi, const SegmentSolver& solve, const Settings& settings,
                   TangentPoint& out, bool& located, double value_tolerance) {
  using Sample = RootSample<TangentPoint>;
  // Each trial point's corrector starts from the chord of the bracket's ends.
  const auto evaluate = [&](double& sigma, const Sample& left, const Sample& right,
                            TangentPoint& at, double& value) {
    const SegmentChord chord{left.x, left.at.point, right.x, right.at.point};
    if (!solve_near(solve, sigma, 0.5 * (left.x + right.x), &chord, at)) return false;
    value = g(at);
    return true;
  };
  const RootSearch search{settings.event_tolerance, value_tolerance, settings.event_max_iterations};
  RootBracket<TangentPoint> r = brent_root<TangentPoint>(
      {lo.sigma, g(lo.point), lo.point}, {hi.sigma, g(hi.point), hi.point}, search, evaluate);
  out = std::move(r.best.at);
  located = r.converged(search);
  return r.accuracy(search);
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
