#include "section/reduced_stiffness.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "laminate_fixtures.hpp"

namespace si {
namespace {

using testing::max_abs;
using testing::paper_material;

// The textbook Q-bar of vam.md 10.1 (Jones 1999, eqs. 2.85-2.86) is the independent reference:
// testing::clt_reduced_stiffness in laminate_fixtures.hpp.
using testing::clt_reduced_stiffness;

// vam.md 5.2: for monoclinic plies the Schur complement of the 3-D stiffness equals the
// textbook rotated plane-stress Q-bar of 10.1. Round-off only: 1e-12 of the largest entry.
TEST(ReducedStiffness, EqualsTextbookQbar_VamSection10_1) {
  const Material m = paper_material();
  for (double angle : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0, -30.0}) {
    const Matrix3d Q = reduced_stiffness(Ply{m, 0.475, angle});
    const Matrix3d ref = clt_reduced_stiffness(m.constants(), angle);
    EXPECT_LE(max_abs(Q - ref), 1e-12 * max_abs(ref)) << "angle " << angle << "\n" << Q;
  }
}

// The sign of Q16 fixes the angle convention: +45 deg couples 11 and 2e12 positively
// (vam.md 11.2, SwiftComp A16 > 0), and -theta flips the sign of Q16 and Q26 only.
TEST(ReducedStiffness, AngleSignFlipsShearCouplingOnly) {
  const Material m = paper_material();
  const Matrix3d plus = reduced_stiffness(Ply{m, 0.475, 30});
  const Matrix3d minus = reduced_stiffness(Ply{m, 0.475, -30});
  EXPECT_GT(reduced_stiffness(Ply{m, 0.475, 45})(0, 1), 0.0);
  Matrix3d flip = Matrix3d::Identity();
  flip(1, 1) = -1;  // 2e12 -> -2e12 under the reflection x2 -> -x2
  EXPECT_LE(max_abs(minus - flip * plus * flip), 1e-12 * max_abs(plus));
}

// Isotropic plane stress: E/(1-nu^2) [[1, 0, nu], [0, (1-nu)/2, 0], [nu, 0, 1]] (Yu order).
TEST(ReducedStiffness, IsotropicPlaneStressClosedForm) {
  const double E = 70000, nu = 0.3;
  const Material m = Material::isotropic("al", E, nu);
  Matrix3d ref;
  ref << 1, 0, nu, 0, (1 - nu) / 2, 0, nu, 0, 1;
  ref *= E / (1 - nu * nu);
  for (double angle : {0.0, 37.0}) {
    const Matrix3d Q = reduced_stiffness(Ply{m, 1.0, angle});
    EXPECT_LE(max_abs(Q - ref), 1e-12 * max_abs(ref)) << Q;
  }
}

TEST(ReducedStiffness, RejectsIndefiniteStiffnessAsNumerical) {
  try {
    reduced_stiffness_yu(-Matrix6d::Identity());
    FAIL() << "accepted a negative definite stiffness";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
  }
}

}  // namespace
}  // namespace si
