// (a b)_jk = a_i C_ijkl b_l (material/stiffness_contraction.hpp) against the isotropic closed form
// (a b) = lambda a b^T + mu (b a^T + (a.b) I) (Ting 1996, eq. 5.2-8 with C_ijkl = lambda d_ij d_kl
// + mu (d_ik d_jl + d_il d_jk)), and its symmetry (a b) = (b a)^T for an orthotropic ply.
#include <gtest/gtest.h>

#include "material/material.hpp"
#include "material/ply_rotation.hpp"
#include "material/stiffness_contraction.hpp"

namespace si {
namespace {

TEST(StiffnessContraction, Isotropic_ClosedForm) {
  const double E = 70000, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const Matrix6d C = Material::isotropic("iso", E, nu).stiffness();
  const Vector3d a(0.3, -1.2, 0.5), b(2.0, 0.7, -0.4);
  const Matrix3d reference =
      lambda * a * b.transpose() + mu * (b * a.transpose() + a.dot(b) * Matrix3d::Identity());
  EXPECT_LT((stiffness_contraction(C, a, b) - reference).norm(), 1e-12 * reference.norm());
}

TEST(StiffnessContraction, RotatedOrthotropicPly_SymmetryAndPositiveAcousticTensor) {
  EngineeringConstants c;
  c.E1 = 130000, c.E2 = c.E3 = 10000, c.G12 = 6000, c.G13 = 3000, c.G23 = 6000;
  c.nu12 = 0.3, c.nu13 = 0.5, c.nu23 = 0.3;
  const Matrix6d C = rotate_stiffness_voigt(Material::orthotropic("ply", c).stiffness(), 30.0);
  const Vector3d a(0.3, -1.2, 0.5), b(2.0, 0.7, -0.4);
  const Matrix3d ab = stiffness_contraction(C, a, b), ba = stiffness_contraction(C, b, a);
  EXPECT_LT((ab - ba.transpose()).norm(), 1e-12 * ab.norm());
  const Matrix3d aa = stiffness_contraction(C, a, a);
  EXPECT_LT((aa - aa.transpose()).norm(), 1e-12 * aa.norm());
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix3d>(aa).eigenvalues().minCoeff(), 0.0);
}

}  // namespace
}  // namespace si
