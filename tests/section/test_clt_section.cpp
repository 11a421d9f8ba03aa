#include "section/clt_section.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../verification_record.hpp"
#include "core/error.hpp"
#include "laminate_fixtures.hpp"
#include "section/reduced_stiffness.hpp"

namespace si {
namespace {

using testing::kPaperPly;
using testing::make_laminate;
using testing::max_abs;
using testing::paper_material;
using testing::repeat;
using testing::symmetric;

// Values printed with two decimals are checked to half a unit of the last printed digit, the
// accuracy of a correctly rounded print.
constexpr double kHalfCent = 0.005 * (1 + 1e-12);

// Also records the non-zero entries of the upper triangle for the report, named `block` + (i, j).
void expect_block_printed(const Matrix3d& computed, const Matrix3d& printed,
                          const std::string& block) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(computed(i, j), printed(i, j), kHalfCent) << "entry " << i << "," << j;
      if (j < i || printed(i, j) == 0) continue;
      test::record_verification_absolute(
          "section-clt", block + "(" + std::to_string(i) + "," + std::to_string(j) + ")",
          printed(i, j), computed(i, j), kHalfCent, "vam.md 12 (2 decimals)");
    }
}

// Mirror-symmetric stacks have B = int Q z dz = 0 (Jones 1999, section 4.5.1); round-off only.
TEST(CltSection, SymmetricLayupsHaveNoCoupling_Jones4_5) {
  const Material m = paper_material();
  const std::vector<std::vector<double>> layups = {
      symmetric(repeat({0, 90}, 2)), symmetric(repeat({45, -45}, 2)), symmetric({0, 45, -45, 90}),
      symmetric({30, -60, 15}), repeat({0}, 8)};
  for (const auto& angles : layups) {
    const Laminate laminate = make_laminate(m, kPaperPly, angles);
    const Matrix6d abd = clt_abd(laminate);
    const double scale = max_abs(a_block(abd)) * laminate.thickness();
    EXPECT_LE(max_abs(b_block(abd)), 1e-14 * scale) << "plies " << angles.size();
    EXPECT_LE(max_abs(abd - abd.transpose()), 1e-14 * max_abs(abd));
    EXPECT_TRUE(is_symmetric_layup(laminate));
  }
}

TEST(CltSection, UnsymmetricLayupsAreRecognised) {
  const Material m = paper_material();
  EXPECT_FALSE(is_symmetric_layup(make_laminate(m, kPaperPly, {0, 90})));
  EXPECT_FALSE(is_symmetric_layup(make_laminate(m, kPaperPly, {45, -45, 45, -45})));
  EXPECT_FALSE(is_symmetric_layup(make_laminate(m, kPaperPly, {0, 45, 90})));
  Laminate thick_top = make_laminate(m, kPaperPly, {0, 0});
  thick_top.plies[1].thickness = 0.5;
  EXPECT_FALSE(is_symmetric_layup(thick_top));
  // 180 deg apart is the same ply.
  EXPECT_TRUE(is_symmetric_layup(make_laminate(m, kPaperPly, {30, 0, -150})));
}

// Antisymmetric [0/90], plies of thickness t: ply 1 (0 deg) in [-t, 0], ply 2 (90 deg) in
// [0, t]. B = sum_k Qbar_k (z_k^2 - z_{k-1}^2)/2 = (t^2/2) (Qbar(90) - Qbar(0)), so with the
// material-axes Q of vam.md 10.1 (Jones 1999, section 4.5.2):
//   B11 = -(Q11 - Q22) t^2/2,  B22 = +(Q11 - Q22) t^2/2,  B12 = B16 = B26 = B66 = 0.
TEST(CltSection, CrossPlyTwoLayerCouplingClosedForm_Jones4_5_2) {
  const Material m = paper_material();
  const double t = kPaperPly;
  const Matrix6d abd = clt_abd(make_laminate(m, t, {0, 90}));
  const Matrix3d Q0 = reduced_stiffness(Ply{m, t, 0});
  const double b11 = -(Q0(0, 0) - Q0(2, 2)) * t * t / 2;
  const Matrix3d B = b_block(abd);
  const double tol = 1e-14 * max_abs(a_block(abd)) * 2 * t;
  EXPECT_NEAR(B(0, 0), b11, 1e-13 * std::abs(b11));
  EXPECT_NEAR(B(2, 2), -b11, 1e-13 * std::abs(b11));
  EXPECT_NEAR(B(0, 2), 0.0, tol);  // B12
  EXPECT_NEAR(B(0, 1), 0.0, tol);  // B16
  EXPECT_NEAR(B(1, 2), 0.0, tol);  // B26
  EXPECT_NEAR(B(1, 1), 0.0, tol);  // B66
  EXPECT_LT(B(0, 0), 0.0);         // the stiff fibres are below the mid-surface in x1
}

// In-plane stress transformation built from the 2x2 tensor rotation sigma' = R sigma R^T,
// applied to unit stress states, Yu order [11, 12, 22]. Independent of the library's T matrix.
Matrix3d stress_rotation_yu(double angle_deg) {
  const double th = angle_deg * M_PI / 180.0;
  Matrix2d R;
  R << std::cos(th), -std::sin(th), std::sin(th), std::cos(th);  // material -> plate axes
  Matrix3d T;
  for (int j = 0; j < 3; ++j) {
    Vector3d unit = Vector3d::Unit(j);
    Matrix2d s;
    s << unit(0), unit(1), unit(1), unit(2);
    const Matrix2d r = R * s * R.transpose();
    T.col(j) = Vector3d(r(0, 0), r(0, 1), r(1, 1));
  }
  return T;
}

// A homogeneous [theta]n stack: A = h T Q T^T and D = h^3/12 T Q T^T with Q the material-axes
// reduced stiffness (vam.md 10.1) and T the tensor rotation of stresses (engineering strains
// transform with T^-T, so Q-bar = T Q T^T); B = 0.
TEST(CltSection, RotatedUnidirectionalEqualsTensorRotation) {
  const Material m = paper_material();
  const Matrix3d Q = reduced_stiffness(Ply{m, 1.0, 0});
  for (double angle : {0.0, 20.0, 45.0, -60.0, 90.0, 135.0}) {
    const Laminate laminate = make_laminate(m, kPaperPly, repeat({angle}, 4));
    const double h = laminate.thickness();
    const Matrix6d abd = clt_abd(laminate);
    const Matrix3d T = stress_rotation_yu(angle);
    const Matrix3d Qbar = T * Q * T.transpose();
    EXPECT_LE(max_abs(a_block(abd) - h * Qbar), 1e-12 * h * max_abs(Q)) << angle;
    EXPECT_LE(max_abs(d_block(abd) - h * h * h / 12 * Qbar), 1e-12 * h * h * h / 12 * max_abs(Q))
        << angle;
    EXPECT_LE(max_abs(b_block(abd)), 1e-14 * h * h * max_abs(Q)) << angle;
  }
}

// vam.md section 12 reference values (paper material, 0.475 mm plies, mid-surface, Yu order),
// printed with two decimals.
TEST(CltSection, IndentationLayupsUnidirectional_VamSection12) {
  const Matrix6d abd = clt_abd(make_laminate(paper_material(), kPaperPly, repeat({0}, 8)));
  Matrix3d A, D;
  A << 497443.84, 0, 11479.47, 0, 22800.00, 0, 11479.47, 0, 38264.91;
  D << 598590.76, 0, 13813.63, 0, 27436.00, 0, 13813.63, 0, 46045.44;
  expect_block_printed(a_block(abd), A, "[0]8 A");
  expect_block_printed(d_block(abd), D, "[0]8 D");
}

TEST(CltSection, IndentationLayupsCrossPly_VamSection12) {
  const Matrix6d abd =
      clt_abd(make_laminate(paper_material(), kPaperPly, symmetric(repeat({0, 90}, 2))));
  Matrix3d A, D;
  A << 267854.38, 0, 11479.47, 0, 22800.00, 0, 11479.47, 0, 267854.38;
  D << 425920.35, 0, 13813.63, 0, 27436.00, 0, 13813.63, 0, 218715.85;
  expect_block_printed(a_block(abd), A, "[0/90]2S A");
  expect_block_printed(d_block(abd), D, "[0/90]2S D");
}

// SwiftComp 2.1 output of the fixture sgio tests/fixtures/swiftcomp/sg12rm_line5_sc21.sg.k
// (vam.md 11.2): [45/0/45/0/45], printed in the conventional order [e11, e22, 2e12, k11, k22,
// 2k12] with 8 significant digits, so 1e-7 relative is the print's accuracy.
TEST(CltSection, SwiftCompPlateStiffness_VamSection11_2) {
  EngineeringConstants c;
  c.E1 = 1.883e7;
  c.E2 = c.E3 = 1.317e6;
  c.G12 = c.G13 = 7.672e5;
  c.G23 = 5.065e5;
  c.nu12 = c.nu13 = 0.32;
  c.nu23 = 0.30;
  const Material m = Material::orthotropic("sc", c);
  Laminate laminate;
  const double t[5] = {0.0072, 0.0288, 0.0144, 0.0288, 0.0072};
  const double angle[5] = {45, 0, 45, 0, 45};
  for (int k = 0; k < 5; ++k) laminate.plies.push_back(Ply{m, t[k], angle[k]});
  const Matrix6d conv = swap_yu_conventional_order(clt_abd(laminate));

  const auto expect_rel = [](double computed, double printed) {
    EXPECT_NEAR(computed, printed, 1e-7 * std::abs(printed));
  };
  expect_rel(conv(0, 0), 1.2667447e6);
  expect_rel(conv(0, 1), 1.5457201e5);
  expect_rel(conv(0, 2), 1.2700320e5);
  expect_rel(conv(1, 2), 1.2700320e5);
  expect_rel(conv(1, 1), 2.5071910e5);
  expect_rel(conv(2, 2), 1.8418301e5);
  expect_rel(conv(3, 3), 723.75165);
  expect_rel(conv(3, 4), 116.52875);
  expect_rel(conv(3, 5), 100.95230);
  expect_rel(conv(4, 5), 100.95230);
  expect_rel(conv(4, 4), 179.48706);
  expect_rel(conv(5, 5), 134.94916);
  EXPECT_LE(max_abs(b_block(conv)), 1e-14 * max_abs(a_block(conv)) * laminate.thickness());
}

// The order permutation {0, 2, 1, 3, 5, 4} (vam.md 13) moves A16 (Yu (0, 1)) to (0, 2) and is
// its own inverse.
TEST(CltSection, ConventionalOrderPermutation_VamSection13) {
  Matrix6d abd;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) abd(i, j) = 10 * i + j;
  const Matrix6d conv = swap_yu_conventional_order(abd);
  EXPECT_EQ(conv(0, 2), abd(0, 1));
  EXPECT_EQ(conv(0, 1), abd(0, 2));
  EXPECT_EQ(conv(4, 5), abd(5, 4));
  EXPECT_EQ(swap_yu_conventional_order(conv), abd);
}

TEST(CltSection, SpeciallyOrthotropicDetection_Jones4_3) {
  const Material m = paper_material();
  const auto special = [&](const std::vector<double>& angles) {
    return is_specially_orthotropic(clt_abd(make_laminate(m, kPaperPly, angles)), 1e-12);
  };
  EXPECT_TRUE(special(symmetric(repeat({0, 90}, 2))));
  EXPECT_TRUE(special(repeat({0}, 8)));
  EXPECT_FALSE(special(symmetric(repeat({45, -45}, 2))));  // D16 != 0
  EXPECT_FALSE(special({0, 90}));                          // B != 0
  EXPECT_THROW(is_specially_orthotropic(Matrix6d::Identity(), -1.0), Error);
}

// Isotropic plate, vam.md 11.1: A = E h/(1-nu^2) [[1, 0, nu], [0, (1-nu)/2, 0], [nu, 0, 1]],
// D = E h^3/(12(1-nu^2)) (same), B = 0.
TEST(CltSection, IsotropicPlateClosedForm_VamSection11_1) {
  const double E = 1, nu = 0.3, h = 1;
  const Matrix6d abd = clt_abd(make_laminate(Material::isotropic("iso", E, nu), h / 3, {0, 0, 0}));
  Matrix3d shape;
  shape << 1, 0, nu, 0, (1 - nu) / 2, 0, nu, 0, 1;
  const Matrix3d A = E * h / (1 - nu * nu) * shape;
  const Matrix3d D = E * h * h * h / (12 * (1 - nu * nu)) * shape;
  EXPECT_LE(max_abs(a_block(abd) - A), 1e-14 * max_abs(A));
  EXPECT_LE(max_abs(d_block(abd) - D), 1e-14 * max_abs(D));
  EXPECT_LE(max_abs(b_block(abd)), 1e-15 * max_abs(A) * h);
}

TEST(CltSection, RejectsEmptyLaminate) {
  try {
    clt_abd(Laminate{});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
  }
}

}  // namespace
}  // namespace si
