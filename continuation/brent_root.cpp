#include "continuation/brent_root.hpp"

#include <algorithm>

namespace si::cont {

std::optional<double> brent_interpolated_step(double a_x, double a_f, double b_x, double b_f,
                                              double c_x, double c_f, double half_width,
                                              double previous_step, double tolerance) {
  const double s = b_f / a_f;
  double p = 0.0, q = 0.0;
  if (a_x == c_x) {
    p = 2.0 * half_width * s;
    q = 1.0 - s;
  } else {
    const double qa = a_f / c_f, r = b_f / c_f;
    p = s * (2.0 * half_width * qa * (qa - r) - (b_x - a_x) * (r - 1.0));
    q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
  }
  if (p > 0.0) q = -q;
  p = std::abs(p);
  if (2.0 * p <
      std::min(3.0 * half_width * q - std::abs(tolerance * q), std::abs(previous_step * q)))
    return p / q;
  return std::nullopt;
}

RootBracket<double> brent_root(const std::function<double(double)>& f, double lo, double hi,
                               double f_lo, double f_hi, const RootSearch& search) {
  // The payload is the abscissa itself (unused): a scalar function has nothing to carry.
  return brent_root<double>({lo, f_lo, lo}, {hi, f_hi, hi}, search,
                            [&f](double& x, const RootSample<double>&, const RootSample<double>&,
                                 double& at, double& value) {
                              at = x;
                              value = f(x);
                              return true;
                            });
}

}  // namespace si::cont
