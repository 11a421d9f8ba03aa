#include "section/transverse_shear.hpp"

#include <array>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "section/clt_section.hpp"
#include "section/reduced_stiffness.hpp"

namespace si {
namespace {

// Transverse-shear block of a ply stiffness in Yu order: rows/cols 3, 4 = [13, 23]. Taken from
// the rotated 3-D stiffness rather than hand formulas so that FSDT and VAM share the convention.
Matrix2d transverse_shear_block(const Ply& ply) {
  return ply.stiffness_yu().block<2, 2>(3, 3);
}

// 3-point Gauss-Legendre on [-1, 1]: exact to degree 5. Within a ply the equilibrium shear
// stress is quadratic in x3 (linear stress gradient integrated once), so tau^T S tau is quartic.
constexpr std::array<double, 3> kGaussX = {-0.7745966692414833770, 0.0, 0.7745966692414833770};
constexpr std::array<double, 3> kGaussW = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

// Shear-stress profile of one unit state, evaluated ply by ply. In ply k, with the CLT
// mid-surface strain gradient d = [m; b] (membrane, curvature), the in-plane stress gradient is
// Q_k (m + x3 b); its rows `rows` are integrated from the bottom face (vam.md 10.3, step 3):
//   tau(x3) = tau(z_{k-1}) - Q_k,rows [ m (x3 - z_{k-1}) + b (x3^2 - z_{k-1}^2) / 2 ].
class ShearProfile {
 public:
  ShearProfile(const Vector6d& d, std::array<int, 2> rows) : d_(d), rows_(rows) {}

  // Shear stress at x3 in the ply with reduced stiffness Q starting at z0 with stress tau0.
  Vector2d at(const Matrix3d& Q, double z0, const Vector2d& tau0, double x3) const {
    const Vector3d integral =
        Q * (d_.head<3>() * (x3 - z0) + d_.tail<3>() * (0.5 * (x3 * x3 - z0 * z0)));
    return tau0 - Vector2d(integral(rows_[0]), integral(rows_[1]));
  }

 private:
  Vector6d d_;
  std::array<int, 2> rows_;
};

Matrix6d mid_surface_abd(const Laminate& laminate) {
  Laminate mid = laminate;
  mid.reference_offset = 0.0;
  return clt_abd(mid);
}

}  // namespace

Matrix2d fsdt_shear_stiffness(const Laminate& laminate, double k) {
  if (!(k > 0.0) || !std::isfinite(k))
    throw_input("shear correction factor must be positive and finite",
                Where{"", "shear_correction", std::to_string(k), 0});
  laminate.validate();
  Matrix2d G = Matrix2d::Zero();
  for (const Ply& ply : laminate.plies) G += ply.thickness * transverse_shear_block(ply);
  return k * G;
}

Matrix2d equilibrium_shear_stiffness(const Laminate& laminate) {
  const Matrix6d abd = mid_surface_abd(laminate);  // validates
  const Eigen::LDLT<Matrix6d> abd_ldlt(abd);
  if (abd_ldlt.info() != Eigen::Success || !abd_ldlt.isPositive())
    throw_numerical("laminate ABD matrix is not positive definite");

  // Unit states: dM11/dx1 = 1 (Yu index 3) with tau = -int [ds11, ds12]/dx1 (Yu rows 0, 1), and
  // dM22/dx2 = 1 (index 5) with tau = -int [ds12, ds22]/dx2 (rows 1, 2).
  const std::array<ShearProfile, 2> states = {
      ShearProfile(abd_ldlt.solve(Vector6d::Unit(3)), {0, 1}),
      ShearProfile(abd_ldlt.solve(Vector6d::Unit(5)), {1, 2})};

  const auto z = laminate.interfaces();
  std::array<Vector2d, 2> tau0 = {Vector2d::Zero(), Vector2d::Zero()};
  Matrix2d F = Matrix2d::Zero();
  for (size_t k = 0; k < laminate.plies.size(); ++k) {
    const Ply& ply = laminate.plies[k];
    const Matrix3d Q = reduced_stiffness(ply);
    const Matrix2d S_s = transverse_shear_block(ply).inverse();
    const double half = 0.5 * (z[k + 1] - z[k]);
    const double mid = 0.5 * (z[k + 1] + z[k]);
    for (size_t g = 0; g < kGaussX.size(); ++g) {
      const double x3 = mid + half * kGaussX[g];
      Matrix2d tau;  // columns: state 1, state 2
      for (int a = 0; a < 2; ++a) tau.col(a) = states[a].at(Q, z[k], tau0[a], x3);
      F += (half * kGaussW[g]) * tau.transpose() * S_s * tau;
    }
    for (int a = 0; a < 2; ++a) tau0[a] = states[a].at(Q, z[k], tau0[a], z[k + 1]);
  }
  F = 0.5 * (F + F.transpose());
  const Eigen::LLT<Matrix2d> f_llt(F);
  if (f_llt.info() != Eigen::Success)
    throw_numerical("complementary shear energy matrix is not positive definite");
  const Matrix2d G = f_llt.solve(Matrix2d::Identity());
  return 0.5 * (G + G.transpose());
}

}  // namespace si
