// The Davies-Zhang delamination threshold against its published formula: for an isotropic plate
// P_c^2 = 8 pi^2 E h^3 G_IIc / (9 (1 - nu^2)) (Davies & Zhang 1995), and for three lay-ups the
// formula with the effective stiffness worked by hand from the textbook CLT D matrix
// (laminate_fixtures.hpp, independent of the section analysis).
#include "damage/delamination_threshold.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../section/laminate_fixtures.hpp"
#include "core/error.hpp"
#include "material/material_library.hpp"
#include "section/clt_section.hpp"

namespace si {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(DelaminationThreshold, IsotropicPlateIsDaviesZhangInEAndH) {
  const double E = 70000, nu = 0.3, h = 4, G = 0.8;
  const double D = E * h * h * h / (12 * (1 - nu * nu));
  Matrix3d Dm;
  Dm << D, 0, nu * D, 0, (1 - nu) / 2 * D, 0, nu * D, 0, D;  // Yu order k11, k12+k21, k22
  const double expected = std::sqrt(8 * kPi * kPi * E * h * h * h * G / (9 * (1 - nu * nu)));
  for (auto choice :
       {EffectiveBendingStiffness::kGeometricMean, EffectiveBendingStiffness::kOlsson}) {
    const DelaminationThreshold t = delamination_threshold(Dm, G, choice);
    EXPECT_NEAR(t.load, expected, 1e-12 * expected);
    EXPECT_NEAR(t.anisotropy, 1.0, 1e-15);  // (nu D + (1 - nu) D) / D
    EXPECT_NEAR(t.D_effective, D, 1e-12 * D);
  }
}

// P_c = pi sqrt(32 D* G_IIc / 3) on the paper's material, 8 plies of 0.475 mm, with
// D* = sqrt(D11 D22) and Olsson's D* = sqrt(D11 D22)(1 + (D12 + 2 D66)/sqrt(D11 D22))/2.
TEST(DelaminationThreshold, ThreeLayupsMatchTheFormulaByHand) {
  const Material m = library_material("paper-carbon-epoxy");
  const double G = *m.toughness().get(ToughnessKey::kGIIc);
  for (const auto& angles : {std::vector<double>{0, 90, 0, 90, 90, 0, 90, 0},
                             std::vector<double>{45, -45, 45, -45, -45, 45, -45, 45},
                             std::vector<double>{0, 45, -45, 90, 90, -45, 45, 0}}) {
    const Laminate laminate = testing::make_laminate(m, 0.475, angles);
    const Matrix6d abd = testing::textbook_clt_abd(laminate);
    const double D11 = abd(3, 3), D22 = abd(5, 5), D12 = abd(3, 5), D66 = abd(4, 4);
    const double mean = std::sqrt(D11 * D22);
    const double olsson = mean * (1 + (D12 + 2 * D66) / mean) / 2;
    const DelaminationThreshold g = delamination_threshold(
        d_block(clt_abd(laminate)), G, EffectiveBendingStiffness::kGeometricMean);
    const DelaminationThreshold o =
        delamination_threshold(d_block(clt_abd(laminate)), G, EffectiveBendingStiffness::kOlsson);
    EXPECT_NEAR(g.load, kPi * std::sqrt(32 * mean * G / 3), 1e-10 * g.load);
    EXPECT_NEAR(o.load, kPi * std::sqrt(32 * olsson * G / 3), 1e-10 * o.load);
    EXPECT_EQ(o.G_IIc, G);
    EXPECT_NEAR(o.D12, D12, 1e-9 * D11);
    std::printf(
        "paper material %s: D11 %.0f D22 %.0f N mm, A %.3f, P_c %.0f N (sqrt(D11 D22)), "
        "%.0f N (Olsson)\n",
        angles[1] == 90   ? "[0/90]2S"
        : angles[0] == 45 ? "[45/-45]2S"
                          : "[0/45/-45/90]s",
        D11, D22, o.anisotropy, g.load, o.load);
  }
}

// n equally spaced delaminations: P_c = pi sqrt(32 D G / (n + 2)), lower than for one.
TEST(DelaminationThreshold, SeveralDelaminationsAndBadInput) {
  Matrix3d D = Matrix3d::Identity() * 1000;
  const double one = delamination_threshold(D, 1, EffectiveBendingStiffness::kGeometricMean).load;
  const double three =
      delamination_threshold(D, 1, EffectiveBendingStiffness::kGeometricMean, 3).load;
  EXPECT_NEAR(three / one, std::sqrt(3.0 / 5.0), 1e-14);
  EXPECT_THROW(delamination_threshold(D, -0.5, EffectiveBendingStiffness::kOlsson), Error);
  EXPECT_THROW(delamination_threshold(D, 0.5, EffectiveBendingStiffness::kOlsson, 0), Error);
}

}  // namespace
}  // namespace si
