#include "damage/material_stress.hpp"

#include <cmath>

namespace si {

MaterialStress to_material_axes(const Vector6d& stress_yu, double angle_deg) {
  const double t = angle_deg * std::acos(-1.0) / 180.0;
  const double c = std::cos(t), s = std::sin(t);
  const double sxx = stress_yu(0), txy = stress_yu(1), syy = stress_yu(2);
  const double txz = stress_yu(3), tyz = stress_yu(4), szz = stress_yu(5);
  MaterialStress m;
  m.s11 = c * c * sxx + s * s * syy + 2 * c * s * txy;
  m.s22 = s * s * sxx + c * c * syy - 2 * c * s * txy;
  m.s33 = szz;
  m.s12 = c * s * (syy - sxx) + (c * c - s * s) * txy;
  m.s13 = c * txz + s * tyz;
  m.s23 = c * tyz - s * txz;
  return m;
}

MaterialStress scaled(const MaterialStress& s, double f) {
  return {f * s.s11, f * s.s22, f * s.s33, f * s.s12, f * s.s13, f * s.s23};
}

}  // namespace si
