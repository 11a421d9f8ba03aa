#include "damage/max_stress.hpp"

#include <cmath>

namespace si {
namespace {

// A normal stress against the tensile or compressive strength its sign selects.
FailureIndex normal_ratio(double s, double tension, double compression, FailureMode tension_mode,
                          FailureMode compression_mode) {
  FailureIndex out;
  if (s > 0) {
    out.index = s / tension;
    out.mode = tension_mode;
  } else if (s < 0) {
    out.index = -s / compression;
    out.mode = compression_mode;
  }
  out.criterion_value = out.index;
  return out;
}

FailureIndex shear_ratio(double s, double strength, FailureMode mode) {
  FailureIndex out;
  out.index = out.criterion_value = std::abs(s) / strength;
  out.mode = s != 0 ? mode : FailureMode::kNone;
  return out;
}

}  // namespace

FailureIndex max_stress(const MaterialStress& s, const Strengths& k) {
  using M = FailureMode;
  FailureIndex out = normal_ratio(s.s11, k.X_T, k.X_C, M::kFibreTension, M::kFibreCompression);
  out = governing(out, normal_ratio(s.s22, k.Y_T, k.Y_C, M::kMatrixTension, M::kMatrixCompression));
  out = governing(out, normal_ratio(s.s33, k.Z_T, k.Z_C, M::kNormalTension, M::kNormalCompression));
  out = governing(out, shear_ratio(s.s12, k.S_12, M::kShear12));
  out = governing(out, shear_ratio(s.s13, k.S_13, M::kShear13));
  return governing(out, shear_ratio(s.s23, k.S_23, M::kShear23));
}

}  // namespace si
