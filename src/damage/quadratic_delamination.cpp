#include "damage/quadratic_delamination.hpp"

#include <algorithm>

namespace si {

FailureIndex quadratic_delamination(const MaterialStress& s, const Strengths& k) {
  const double normal = std::max(s.s33, 0.0) / k.Z_T;
  const double a =
      normal * normal + (s.s13 / k.S_13) * (s.s13 / k.S_13) + (s.s23 / k.S_23) * (s.s23 / k.S_23);
  return quadratic_mode(a, 0.0, FailureMode::kDelamination);
}

}  // namespace si
