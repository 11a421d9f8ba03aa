#include "material/ply_rotation.hpp"

#include <gtest/gtest.h>

#include "material_fixtures.hpp"

#include <cmath>

#include "material/material.hpp"

namespace si {
namespace {

using testing::max_abs;

Material generic_material() {
  return Material::orthotropic("generic", testing::generic_constants());
}

// A fully anisotropic SPD stiffness, so that every entry of the rotation is exercised.
Matrix6d anisotropic_stiffness() {
  Matrix6d M;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) M(i, j) = std::sin(1.0 + 3 * i + 7 * j);
  return 1000.0 * (M * M.transpose() + 6 * Matrix6d::Identity());
}

// Voigt index of the tensor pair (i, j), order [11, 22, 33, 23, 13, 12].
int voigt(int i, int j) {
  if (i == j) return i;
  return 6 - i - j;  // {1,2} -> 3, {0,2} -> 4, {0,1} -> 5
}

// Independent reference: C_pqrs = R_pi R_qj R_rk R_sl C_ijkl on the full 3x3x3x3 tensor, with
// R the rotation by +theta about x3 whose columns are the material axes in plate coordinates.
// With engineering shear strains the Voigt stiffness is C_IJ = C_ijkl (no factors of 2).
Matrix6d tensor_rotation(const Matrix6d& C_voigt, double angle_deg) {
  const double th = angle_deg * M_PI / 180.0;
  Matrix3d R;
  R << std::cos(th), -std::sin(th), 0, std::sin(th), std::cos(th), 0, 0, 0, 1;
  double C[3][3][3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) C[i][j][k][l] = C_voigt(voigt(i, j), voigt(k, l));
  Matrix6d out;
  for (int p = 0; p < 3; ++p)
    for (int q = p; q < 3; ++q)
      for (int r = 0; r < 3; ++r)
        for (int s = r; s < 3; ++s) {
          double sum = 0;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              for (int k = 0; k < 3; ++k)
                for (int l = 0; l < 3; ++l)
                  sum += R(p, i) * R(q, j) * R(r, k) * R(s, l) * C[i][j][k][l];
          out(voigt(p, q), voigt(r, s)) = sum;
        }
  return out;
}

// vam.md section 1: "C_std = T C' T^T ... verified against a 4th-order-tensor rotation".
TEST(PlyRotation, EqualsFourthOrderTensorRotation_VamSection1) {
  for (const Matrix6d& C : {generic_material().stiffness(), anisotropic_stiffness()}) {
    for (double angle : {0.0, 10.0, 30.0, 45.0, -45.0, 72.5, 90.0, 135.0, 200.0}) {
      const Matrix6d ref = tensor_rotation(C, angle);
      EXPECT_LE(max_abs(rotate_stiffness_voigt(C, angle) - ref), 1e-13 * max_abs(C))
          << "angle " << angle;
    }
  }
}

// At 90 deg the fibre lies along x2: indices 1 <-> 2 swap, hence Voigt 11 <-> 22 and 23 <-> 13.
TEST(PlyRotation, NinetyDegreesSwapsOneAndTwo) {
  const Matrix6d C = generic_material().stiffness();
  const Matrix6d R = rotate_stiffness_voigt(C, 90);
  const int swap[6] = {1, 0, 2, 4, 3, 5};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      EXPECT_NEAR(R(i, j), C(swap[i], swap[j]), 1e-12 * max_abs(C)) << i << "," << j;
}

// A half turn about x3 maps (x1, x2, x3) to (-x1, -x2, x3): an orthotropic (or any monoclinic)
// ply is unchanged; a general anisotropic one changes the sign of its 23 and 13 rows/columns.
TEST(PlyRotation, HalfTurnIsIdentityForOrthotropic) {
  const Matrix6d C = generic_material().stiffness();
  EXPECT_LE(max_abs(rotate_stiffness_voigt(C, 180) - C), 1e-12 * max_abs(C));
  const Matrix6d A = anisotropic_stiffness();
  const Matrix6d flip = Vector6d(1, 1, 1, -1, -1, 1).asDiagonal();
  EXPECT_LE(max_abs(rotate_stiffness_voigt(A, 180) - flip * A * flip), 1e-12 * max_abs(A));
}

// Yu order [11, 12, 22, 13, 23, 33] = Voigt {0, 5, 1, 4, 3, 2} (vam.md section 1), and a ply
// rotated about x3 is monoclinic: {11, 12, 22, 33} do not couple with {13, 23}.
TEST(PlyRotation, YuOrderAndMonoclinicStructure_VamSection1) {
  const Matrix6d C = anisotropic_stiffness();
  const Matrix6d Y = voigt_to_yu(C);
  EXPECT_EQ(Y(1, 1), C(5, 5));  // 12
  EXPECT_EQ(Y(0, 5), C(0, 2));  // 11-33
  EXPECT_EQ(Y(3, 4), C(4, 3));  // 13-23
  EXPECT_EQ(Y(2, 1), C(1, 5));  // 22-12

  const Matrix6d P = ply_stiffness_yu(generic_material().stiffness(), 33);
  for (int i : {0, 1, 2, 5})
    for (int j : {3, 4}) EXPECT_EQ(P(i, j), 0.0) << i << "," << j;
  EXPECT_NE(P(0, 1), 0.0);  // in-plane shear coupling appears off-axis
  EXPECT_NE(P(3, 4), 0.0);  // and transverse-shear coupling
}

}  // namespace
}  // namespace si
