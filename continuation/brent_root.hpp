// Brent's method for a root of a continuous function bracketed by two samples of opposite signs
// (Brent 1973, "Algorithms for minimization without derivatives", ch. 4): inverse quadratic
// interpolation through the last three samples, the secant through two, and bisection when the
// interpolation does not converge. Superlinear near a simple root, never worse than bisection.
// Each sample may carry a payload (the event locator's solved point; nothing for a scalar
// function), so that one implementation serves the continuation's events and the indentation
// run's critical points.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <utility>

namespace si::cont {

template <class Payload>
struct RootSample {
  double x = 0.0;
  double f = 0.0;
  Payload at{};
};

struct RootSearch {
  double x_tolerance = 0.0;      // stop once the bracket is at most this wide
  double value_tolerance = 0.0;  // or once the best sample has |f| <= this (0: never)
  int max_iterations = 80;
};

// The last bracket: `best` the sample with the smaller |f|, `other` the end of opposite sign.
template <class Payload>
struct RootBracket {
  RootSample<Payload> best;
  RootSample<Payload> other;
  // |best.x - other.x| (0 when best.f is exactly 0).
  double width() const { return best.f == 0.0 ? 0.0 : std::abs(other.x - best.x); }
  bool within_value(double tolerance) const {
    return best.f == 0.0 || std::abs(best.f) <= tolerance;
  }
  // The distance from best to the root estimated by the bracket's secant, |f| / |df/dx|.
  double secant_distance() const { return std::abs(best.f) * width() / std::abs(other.f - best.f); }
  // Whether the search of `search` ended on one of its two tests (not on its iteration count or
  // an unevaluable point).
  bool converged(const RootSearch& search) const {
    return width() <= search.x_tolerance || within_value(search.value_tolerance);
  }
  // How far best may lie from the root: the bracket, or once the value test stopped the search
  // early, the secant's estimate (never more than the bracket).
  double accuracy(const RootSearch& search) const {
    return width() > search.x_tolerance && within_value(search.value_tolerance)
               ? std::min(width(), secant_distance())
               : width();
  }
};

// Brent's step from the best sample b towards the root, or nullopt when the interpolated step is
// not accepted (it leaves the bracket's inner three quarters, or is more than half the step before
// last: the interpolation is not converging); then the caller bisects. a is the previous b, c the
// bracket's other end; inverse quadratic interpolation when a and c differ, else the secant.
std::optional<double> brent_interpolated_step(double a_x, double a_f, double b_x, double b_f,
                                              double c_x, double c_f, double half_width,
                                              double previous_step, double tolerance);

// Brent's iteration from the bracket (lo, hi), lo.f and hi.f of opposite signs. `evaluate(x,
// left, right, at, f)` samples the function at x (it may move x, e.g. off a singular point,
// staying inside the bracket (left.x, right.x)); false, or a NaN f, ends the search with the
// bracket so far.
template <class Payload>
RootBracket<Payload> brent_root(
    RootSample<Payload> lo, RootSample<Payload> hi, const RootSearch& search,
    const std::function<bool(double& x, const RootSample<Payload>& left,
                             const RootSample<Payload>& right, Payload& at, double& f)>& evaluate) {
  using Sample = RootSample<Payload>;
  const auto sign = [](double v) { return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0); };
  // b the best estimate, c the bracket's other end (f(c) of the other sign), a the previous b;
  // d the last step, e the one before.
  Sample a = std::move(lo);
  Sample b = std::move(hi);
  Sample c = b;
  double d = b.x - a.x, e = d;
  const double tolerance = 0.5 * search.x_tolerance;
  const auto small_enough = [&](const Sample& s) {
    return s.f == 0.0 || std::abs(s.f) <= search.value_tolerance;
  };
  for (int it = 0; it < search.max_iterations; ++it) {
    if (sign(b.f) == sign(c.f)) {  // the root lies between a and b
      c = a;
      d = e = b.x - a.x;
    }
    if (std::abs(c.f) < std::abs(b.f)) {  // b: the end nearer the root, a the previous b
      std::swap(b, c);
      a = c;
    }
    const double half_width = 0.5 * (c.x - b.x);
    if (std::abs(half_width) <= tolerance || small_enough(b)) break;
    const std::optional<double> step =
        std::abs(e) >= tolerance && std::abs(a.f) > std::abs(b.f)
            ? brent_interpolated_step(a.x, a.f, b.x, b.f, c.x, c.f, half_width, e, tolerance)
            : std::nullopt;
    e = step ? d : half_width;
    d = step ? *step : half_width;
    Sample trial;
    trial.x = b.x + (std::abs(d) > tolerance ? d : std::copysign(tolerance, half_width));
    const bool b_first = b.x < c.x;
    if (!evaluate(trial.x, b_first ? b : c, b_first ? c : b, trial.at, trial.f) ||
        std::isnan(trial.f))
      break;
    a = std::move(b);
    b = std::move(trial);
  }
  return {std::move(b), std::move(c)};
}

// A scalar function's root in [lo, hi] (f_lo, f_hi of opposite signs): the last bracket.
RootBracket<double> brent_root(const std::function<double(double)>& f, double lo, double hi,
                               double f_lo, double f_hi, const RootSearch& search);

}  // namespace si::cont
