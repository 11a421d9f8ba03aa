#include "contact/hertz_dent.hpp"

#include <cmath>

#include "core/constants.hpp"
#include "core/error.hpp"

namespace si {

DentValue hertz_dent(double r, double alpha, double radius) {
  SI_REQUIRE(radius > 0 && r >= 0, "hertz_dent: the radius must be positive and r >= 0");
  const double depth = std::abs(alpha);
  const double a = std::sqrt(radius * depth);
  DentValue d;
  if (r <= a) {
    d.u = depth - r * r / (2 * radius);
    d.rate = 1;
  } else {
    const double angle = std::asin(a / r);
    d.u = ((2 * a * a - r * r) * angle + a * std::sqrt(r * r - a * a)) / (kPi * radius);
    d.rate = 2 / kPi * angle;
  }
  // Far from the patch the two terms of the outer branch cancel to O(a^3/r) from O(a r): the
  // absolute roundoff, 1e-16 alpha r/a, stays far below any gap tolerance.
  if (alpha < 0) d.u = -d.u;  // odd in alpha; the rate is even
  return d;
}

}  // namespace si
