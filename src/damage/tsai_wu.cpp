#include "damage/tsai_wu.hpp"

#include <cmath>

namespace si {
namespace {

// Largest single-component contribution to F (header).
FailureMode dominant_mode(const MaterialStress& s, const double (&lin)[3], const double (&quad)[3],
                          const double (&shear)[3]) {
  using M = FailureMode;
  const double normal[3] = {s.s11, s.s22, s.s33};
  const M tension[3] = {M::kFibreTension, M::kMatrixTension, M::kNormalTension};
  const M compression[3] = {M::kFibreCompression, M::kMatrixCompression, M::kNormalCompression};
  const double shears[3] = {s.s12, s.s13, s.s23};
  const M shear_modes[3] = {M::kShear12, M::kShear13, M::kShear23};
  double largest = 0;
  M mode = M::kNone;
  for (int i = 0; i < 3; ++i) {
    const double c = lin[i] * normal[i] + quad[i] * normal[i] * normal[i];
    if (c > largest) {
      largest = c;
      mode = normal[i] > 0 ? tension[i] : compression[i];
    }
    const double t = shear[i] * shears[i] * shears[i];
    if (t > largest) {
      largest = t;
      mode = shear_modes[i];
    }
  }
  return mode;
}

}  // namespace

FailureIndex tsai_wu(const MaterialStress& s, const Strengths& k) {
  const double lin[3] = {1 / k.X_T - 1 / k.X_C, 1 / k.Y_T - 1 / k.Y_C, 1 / k.Z_T - 1 / k.Z_C};
  const double quad[3] = {1 / (k.X_T * k.X_C), 1 / (k.Y_T * k.Y_C), 1 / (k.Z_T * k.Z_C)};
  const double shear[3] = {1 / (k.S_12 * k.S_12), 1 / (k.S_13 * k.S_13),
                           1 / (k.S_23 * k.S_23)};  // F66, F55, F44
  const double F12 = -0.5 * std::sqrt(quad[0] * quad[1]);
  const double F13 = -0.5 * std::sqrt(quad[0] * quad[2]);
  const double F23 = -0.5 * std::sqrt(quad[1] * quad[2]);
  const double b = lin[0] * s.s11 + lin[1] * s.s22 + lin[2] * s.s33;
  const double a = quad[0] * s.s11 * s.s11 + quad[1] * s.s22 * s.s22 + quad[2] * s.s33 * s.s33 +
                   shear[0] * s.s12 * s.s12 + shear[1] * s.s13 * s.s13 + shear[2] * s.s23 * s.s23 +
                   2 * F12 * s.s11 * s.s22 + 2 * F13 * s.s11 * s.s33 + 2 * F23 * s.s22 * s.s33;
  FailureIndex out = quadratic_mode(a, b, FailureMode::kNone);
  if (out.index > 0) out.mode = dominant_mode(s, lin, quad, shear);
  return out;
}

}  // namespace si
