// Small fixed-size matrix types shared by all layers.
#pragma once

#include <Eigen/Dense>

namespace si {

using Vector2d = Eigen::Vector2d;
using Vector3d = Eigen::Vector3d;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix2d = Eigen::Matrix2d;
using Matrix3d = Eigen::Matrix3d;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// out(i, j) = m(p[i], p[j]): reorders the rows and columns of a 6x6 matrix (a change of
// strain-component ordering, e.g. Voigt to Yu).
inline Matrix6d permuted(const Matrix6d& m, const int (&p)[6]) {
  Matrix6d out;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) out(i, j) = m(p[i], p[j]);
  return out;
}

}  // namespace si
