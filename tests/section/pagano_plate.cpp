#include "pagano_plate.hpp"

#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <stdexcept>

namespace si::testing {

PaganoPlate::PaganoPlate(const Laminate& laminate, double a, double b, double q0)
    : p_(std::acos(-1.0) / a), r_(std::acos(-1.0) / b), z_(laminate.interfaces()) {
  for (const Ply& ply : laminate.plies) {
    // Yu order [11, 12, 22, 13, 23, 33] in plate axes.
    const Matrix6d C = ply.stiffness_yu();
    const double scale = C.cwiseAbs().maxCoeff();
    if (std::abs(C(0, 1)) + std::abs(C(1, 2)) + std::abs(C(1, 5)) + std::abs(C(3, 4)) >
        1e-12 * scale)
      throw std::invalid_argument("Pagano's solution needs plies orthotropic in plate axes");
    plies_.push_back(
        {C(0, 0), C(0, 2), C(0, 5), C(2, 2), C(2, 5), C(5, 5), C(4, 4), C(3, 3), C(1, 1)});
  }
  // Transfer matrix of the whole stack, s_top = P s_bottom.
  const int n = static_cast<int>(plies_.size());
  std::vector<Matrix6d> transfer(n);
  Matrix6d P = Matrix6d::Identity();
  for (int k = 0; k < n; ++k) {
    const Matrix6d A = system_matrix(plies_[k]) * (z_[k + 1] - z_[k]);
    transfer[k] = A.exp();
    P = (transfer[k] * P).eval();
  }
  // X = Y = 0 and Z = -q0 at the top with s_bottom = [U0, V0, W0, 0, 0, 0].
  const Matrix3d M = P.block<3, 3>(3, 0);
  const Vector3d displacement = M.fullPivLu().solve(Vector3d(0, 0, -q0));
  Vector6d s = Vector6d::Zero();
  s.head<3>() = displacement;
  for (int k = 0; k < n; ++k) {
    bottom_states_.push_back(s);
    s = (transfer[k] * s).eval();
  }
}

// s' = A s from the constitutive law and the three equilibrium equations (header).
Matrix6d PaganoPlate::system_matrix(const PlyConstants& c) const {
  const double p = p_, r = r_;
  // W' = (Z + p C13 U + r C23 V) / C33 as a row over s.
  Eigen::Matrix<double, 1, 6> dW;
  dW << p * c.C13 / c.C33, r * c.C23 / c.C33, 0, 0, 0, 1.0 / c.C33;
  // Amplitudes of sigma_xx, sigma_yy (~ sin sin) and tau_xy (~ cos cos) as rows over s.
  Eigen::Matrix<double, 1, 6> Sx, Sy, T;
  Sx << -p * c.C11, -r * c.C12, 0, 0, 0, 0;
  Sx += c.C13 * dW;
  Sy << -p * c.C12, -r * c.C22, 0, 0, 0, 0;
  Sy += c.C23 * dW;
  T << c.C66 * r, c.C66 * p, 0, 0, 0, 0;

  Matrix6d A = Matrix6d::Zero();
  A(0, 3) = 1.0 / c.C55;  // U' = X / C55 - p W
  A(0, 2) = -p;
  A(1, 4) = 1.0 / c.C44;  // V' = Y / C44 - r W
  A(1, 2) = -r;
  A.row(2) = dW;
  A.row(3) = -p * Sx + r * T;  // sigma_xx,x + tau_xy,y + tau_xz,z = 0
  A.row(4) = p * T - r * Sy;   // tau_xy,x + sigma_yy,y + tau_yz,z = 0
  A(5, 3) = p;                 // tau_xz,x + tau_yz,y + sigma_zz,z = 0
  A(5, 4) = r;
  return A;
}

PaganoPoint PaganoPlate::fields(const PlyConstants& c, const Vector6d& s) const {
  const double U = s(0), V = s(1), W = s(2), X = s(3), Y = s(4), Z = s(5);
  const double dW = (Z + p_ * c.C13 * U + r_ * c.C23 * V) / c.C33;
  PaganoPoint out;
  out.sigma_xx = -p_ * c.C11 * U - r_ * c.C12 * V + c.C13 * dW;
  out.sigma_yy = -p_ * c.C12 * U - r_ * c.C22 * V + c.C23 * dW;
  out.sigma_zz = Z;
  out.tau_xy = c.C66 * (r_ * U + p_ * V);
  out.tau_xz = X;
  out.tau_yz = Y;
  out.u = U;
  out.v = V;
  out.w = W;
  return out;
}

PaganoPoint PaganoPlate::at(double z, int ply) const {
  const int n = static_cast<int>(plies_.size());
  if (ply < 0) {
    ply = n - 1;
    for (int k = 0; k < n; ++k)
      if (z < z_[k + 1]) {
        ply = k;
        break;
      }
  }
  const Matrix6d A = system_matrix(plies_[ply]) * (z - z_[ply]);
  return fields(plies_[ply], A.exp() * bottom_states_[ply]);
}

}  // namespace si::testing
