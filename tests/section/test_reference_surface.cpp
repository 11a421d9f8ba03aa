#include "section/reference_surface.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "core/error.hpp"
#include "laminate_fixtures.hpp"
#include "section/clt_section.hpp"
#include "section/reduced_stiffness.hpp"

namespace si {
namespace {

using testing::kPaperPly;
using testing::make_laminate;
using testing::max_abs;
using testing::paper_material;

// An unsymmetric stack, so that B != 0 about the mid-surface and every term of the shift acts.
Laminate unsymmetric_laminate() {
  return make_laminate(paper_material(), kPaperPly, {0, 45, -30, 90, 60});
}

// Shifting is a change of coordinate along x3: by e then by -e is the identity (vam.md 6.5).
TEST(ReferenceSurface, ShiftThereAndBackIsIdentity) {
  const Matrix6d abd = clt_abd(unsymmetric_laminate());
  const Matrix6d back = shift_reference(shift_reference(abd, 0.7), -0.7);
  EXPECT_LE(max_abs(back - abd), 1e-13 * max_abs(abd));
  EXPECT_GT(max_abs(shift_reference(abd, 0.7) - abd), 1e-3 * max_abs(abd));  // it did move
}

TEST(ReferenceSurface, ShiftsCompose) {
  const Matrix6d abd = clt_abd(unsymmetric_laminate());
  const Matrix6d twice = shift_reference(shift_reference(abd, 0.3), -1.1);
  EXPECT_LE(max_abs(twice - shift_reference(abd, -0.8)), 1e-13 * max_abs(abd));
}

// Reference on the bottom face (offset -h/2): clt_abd must equal the shifted mid-surface ABD and
// the textbook integration with z measured from the bottom face (Jones 1999, eq. 4.22):
// A, B, D = sum_k Q_k (zeta_k - zeta_{k-1}), (zeta_k^2 - zeta_{k-1}^2)/2, (zeta_k^3 - ...)/3.
TEST(ReferenceSurface, BottomFaceReferenceEqualsIntegrationFromBottom_Jones4_22) {
  Laminate laminate = unsymmetric_laminate();
  const double h = laminate.thickness();
  const Matrix6d mid = clt_abd(laminate);
  laminate.reference_offset = -0.5 * h;
  const Matrix6d bottom = clt_abd(laminate);

  Matrix3d A = Matrix3d::Zero(), B = Matrix3d::Zero(), D = Matrix3d::Zero();
  double zeta0 = 0;
  for (const Ply& ply : laminate.plies) {
    const double zeta1 = zeta0 + ply.thickness;
    const Matrix3d Q = reduced_stiffness(ply);
    A += Q * (zeta1 - zeta0);
    B += Q * (zeta1 * zeta1 - zeta0 * zeta0) / 2;
    D += Q * (zeta1 * zeta1 * zeta1 - zeta0 * zeta0 * zeta0) / 3;
    zeta0 = zeta1;
  }

  EXPECT_LE(max_abs(bottom - shift_reference(mid, -0.5 * h)), 1e-14 * max_abs(bottom));
  // Each block against its own scale: A ~ Q h, B ~ Q h^2, D ~ Q h^3 / 3.
  EXPECT_LE(max_abs(a_block(bottom) - A), 1e-13 * max_abs(A));
  EXPECT_LE(max_abs(b_block(bottom) - B), 1e-13 * max_abs(A) * h);
  EXPECT_LE(max_abs(b_block(bottom.transpose()) - B), 1e-13 * max_abs(A) * h);
  EXPECT_LE(max_abs(d_block(bottom) - D), 1e-13 * max_abs(D));
}

TEST(ReferenceSurface, RejectsNonFiniteOffsetNamingTheKey) {
  const Matrix6d abd = Matrix6d::Identity();
  try {
    shift_reference(abd, std::numeric_limits<double>::quiet_NaN());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().key, "laminate.reference_offset");
  }
}

}  // namespace
}  // namespace si
