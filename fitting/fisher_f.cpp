#include "fitting/fisher_f.hpp"

#include <limits>
#include <stdexcept>

#include "fitting/student_t.hpp"

namespace si::fit {

double fisher_f_cdf(double x, double d1, double d2) {
  if (!(d1 > 0.0) || !(d2 > 0.0)) throw std::invalid_argument("fisher_f_cdf: needs d1, d2 > 0");
  if (!(x > 0.0)) return 0.0;
  if (x == std::numeric_limits<double>::infinity()) return 1.0;
  return incomplete_beta(0.5 * d1, 0.5 * d2, d1 * x / (d1 * x + d2));
}

double fisher_f_quantile(double p, double d1, double d2) {
  if (!(p > 0.0 && p < 1.0)) throw std::invalid_argument("fisher_f_quantile: needs 0 < p < 1");
  if (!(d1 > 0.0) || !(d2 > 0.0))
    throw std::invalid_argument("fisher_f_quantile: needs d1, d2 > 0");
  double lo = 0.0;
  double hi = 1.0;
  while (fisher_f_cdf(hi, d1, d2) < p) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e300) return std::numeric_limits<double>::infinity();
  }
  for (int i = 0; i < 200 && hi - lo > 4 * std::numeric_limits<double>::epsilon() * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fisher_f_cdf(mid, d1, d2) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace si::fit
