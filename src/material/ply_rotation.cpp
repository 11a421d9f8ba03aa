#include "material/ply_rotation.hpp"

#include <cmath>

namespace si {

Matrix6d rotate_stiffness_voigt(const Matrix6d& C_material, double angle_deg) {
  const double th = angle_deg * M_PI / 180.0;
  const double c = std::cos(th);
  const double s = std::sin(th);
  // Stress transformation material -> plate axes (vam.md section 1): sigma_plate = T sigma_mat,
  // eps_mat = T^T eps_plate (engineering shears), hence C_plate = T C' T^T.
  Matrix6d T;
  T << c * c, s * s, 0, 0, 0, -2 * c * s,  //
      s * s, c * c, 0, 0, 0, 2 * c * s,    //
      0, 0, 1, 0, 0, 0,                    //
      0, 0, 0, c, s, 0,                    //
      0, 0, 0, -s, c, 0,                   //
      c * s, -c * s, 0, 0, 0, c * c - s * s;
  Matrix6d C = T * C_material * T.transpose();
  return 0.5 * (C + C.transpose());
}

Matrix6d voigt_to_yu(const Matrix6d& C_voigt) {
  static constexpr int p[6] = {0, 5, 1, 4, 3, 2};
  return permuted(C_voigt, p);
}

Matrix6d ply_stiffness_yu(const Matrix6d& C_material, double angle_deg) {
  return voigt_to_yu(rotate_stiffness_voigt(C_material, angle_deg));
}

}  // namespace si
