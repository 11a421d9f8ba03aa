#include "material/stiffness_contraction.hpp"

namespace si {
namespace {

// Voigt index of the tensor index pair (i, j): 11 22 33 23 13 12 -> 0..5.
constexpr int kVoigt[3][3] = {{0, 5, 4}, {5, 1, 3}, {4, 3, 2}};

}  // namespace

Matrix3d stiffness_contraction(const Matrix6d& C_voigt, const Vector3d& a, const Vector3d& b) {
  Matrix3d out = Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < 3; ++l) {
      const double ab = a[i] * b[l];
      if (ab == 0.0) continue;
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) out(j, k) += ab * C_voigt(kVoigt[i][j], kVoigt[k][l]);
    }
  return out;
}

}  // namespace si
