#include "damage/hashin.hpp"

namespace si {
namespace {

// (s12^2 + s13^2) / S_12^2: the axial shear term shared by three modes.
double axial_shear(const MaterialStress& s, const Strengths& k) {
  return (s.s12 * s.s12 + s.s13 * s.s13) / (k.S_12 * k.S_12);
}

// (s23^2 - s22 s33) / S_23^2, Hashin's second transverse invariant term.
double transverse_shear(const MaterialStress& s, const Strengths& k) {
  return (s.s23 * s.s23 - s.s22 * s.s33) / (k.S_23 * k.S_23);
}

}  // namespace

FailureIndex hashin_fibre(const MaterialStress& s, const Strengths& k) {
  if (s.s11 > 0) {
    const double a = (s.s11 / k.X_T) * (s.s11 / k.X_T) + axial_shear(s, k);
    return quadratic_mode(a, 0.0, FailureMode::kFibreTension);
  }
  if (s.s11 < 0) {
    const double a = (s.s11 / k.X_C) * (s.s11 / k.X_C);
    return quadratic_mode(a, 0.0, FailureMode::kFibreCompression);
  }
  return {};
}

FailureIndex hashin_matrix(const MaterialStress& s, const Strengths& k) {
  const double I1 = s.s22 + s.s33;
  const double shear = transverse_shear(s, k) + axial_shear(s, k);
  if (I1 >= 0) {
    const double a = (I1 / k.Y_T) * (I1 / k.Y_T) + shear;
    return quadratic_mode(a, 0.0, FailureMode::kMatrixTension);
  }
  const double ratio = k.Y_C / (2.0 * k.S_23);
  const double b = (ratio * ratio - 1.0) * I1 / k.Y_C;
  const double a = I1 * I1 / (4.0 * k.S_23 * k.S_23) + shear;
  return quadratic_mode(a, b, FailureMode::kMatrixCompression);
}

FailureIndex hashin(const MaterialStress& s, const Strengths& k) {
  return governing(hashin_fibre(s, k), hashin_matrix(s, k));
}

}  // namespace si
