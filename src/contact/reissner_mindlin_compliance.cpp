#include "contact/reissner_mindlin_compliance.hpp"

#include <cmath>

namespace si {

double reissner_mindlin_compliance(const Matrix3d& D, const Matrix2d& G, double phi_rad,
                                   double wavenumber) {
  const double k = wavenumber;
  const Vector2d kk(k * std::cos(phi_rad), k * std::sin(phi_rad));
  Eigen::Matrix<double, 3, 2> Bk;
  Bk << kk[0], 0, kk[1], kk[0], 0, kk[1];
  Matrix3d K;
  K(0, 0) = kk.dot(G * kk);
  K.block<2, 1>(1, 0) = G * kk;
  K.block<1, 2>(0, 1) = (G * kk).transpose();
  K.block<2, 2>(1, 1) = Bk.transpose() * D * Bk + G;
  return k * K.ldlt().solve(Vector3d(1, 0, 0))[0];
}

}  // namespace si
