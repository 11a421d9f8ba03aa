#include "damage/failure_index.hpp"

#include <cmath>

namespace si {

double inverse_load_factor(double a, double b) {
  // 1/R for a R^2 + b R = 1: rationalising R = (-b + sqrt(b^2 + 4a)) / (2a) gives
  // 1/R = (b + sqrt(b^2 + 4a)) / 2, which also holds for a = 0 (1/R = b if b > 0, else no root).
  const double discriminant = b * b + 4.0 * a;
  if (discriminant < 0.0) return 0.0;
  return std::max(0.0, 0.5 * (b + std::sqrt(discriminant)));
}

FailureIndex quadratic_mode(double a, double b, FailureMode mode) {
  FailureIndex out;
  out.index = inverse_load_factor(a, b);
  out.criterion_value = a + b;
  out.mode = out.index > 0.0 ? mode : FailureMode::kNone;
  return out;
}

FailureIndex governing(const FailureIndex& first, const FailureIndex& second) {
  return second.index > first.index ? second : first;
}

}  // namespace si
