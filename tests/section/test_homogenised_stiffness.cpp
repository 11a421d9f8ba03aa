// The homogenised 3-D stiffness of a ply stack (section/homogenised_stiffness.hpp) against
// independent references:
//  * one ply is its own homogenised medium;
//  * its plane-stress reduction is A/h of the textbook classical laminate theory (a different
//    path: engineering constants -> reduced stiffness -> rotation, laminate_fixtures.hpp);
//  * the out-of-plane shear moduli of isotropic layers combine in series (harmonic mean:
//    tractions sigma_13, sigma_23 continuous) and the in-plane shear modulus in parallel
//    (arithmetic mean: strain g12 continuous) - Postma (1955)'s springs;
//  * slicing the laminate keeps the plies, partial plies by their part inside the slice.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "laminate_fixtures.hpp"
#include "material/ply_rotation.hpp"
#include "section/homogenised_stiffness.hpp"

namespace si {
namespace {

using testing::kPaperPly;
using testing::make_laminate;
using testing::paper_material;
using testing::textbook_clt_abd;

// Plane-stress reduction of a Voigt stiffness onto [e11, e22, g12].
Matrix3d plane_stress(const Matrix6d& C) {
  const int p[3] = {0, 1, 5}, t[3] = {2, 3, 4};
  Matrix3d Cpp, Cpt, Ctt;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      Cpp(i, j) = C(p[i], p[j]);
      Cpt(i, j) = C(p[i], t[j]);
      Ctt(i, j) = C(t[i], t[j]);
    }
  return Cpp - Cpt * Ctt.inverse() * Cpt.transpose();
}

TEST(HomogenisedStiffness, SinglePly_IsItself) {
  const Matrix6d C = rotate_stiffness_voigt(paper_material().stiffness(), 30.0);
  const Matrix6d H = homogenised_stiffness({{C, 0.7}});
  EXPECT_LT((H - C).norm(), 1e-12 * C.norm());
}

TEST(HomogenisedStiffness, PlaneStressReduction_IsAOverHOfTextbookClt) {
  for (const std::vector<double>& angles : {std::vector<double>{0, 90, 0, 90, 90, 0, 90, 0},
                                            {45, -45, 45, -45, -45, 45, -45, 45},
                                            {30, -60, 15, 90}}) {
    const Laminate lam = make_laminate(paper_material(), kPaperPly, angles);
    const double h = lam.thickness();
    const Matrix3d Q = plane_stress(homogenised_stiffness(laminate_layers(lam, -h / 2, h / 2)));
    // Textbook A in Yu order [11, 12, 22] -> [11, 22, 12].
    const Matrix3d A_yu = textbook_clt_abd(lam).topLeftCorner<3, 3>() / h;
    const int perm[3] = {0, 2, 1};
    Matrix3d A;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A(i, j) = A_yu(perm[i], perm[j]);
    EXPECT_LT((Q - A).norm(), 1e-10 * A.norm()) << Q << "\n\n" << A;
  }
}

TEST(HomogenisedStiffness, IsotropicLayers_ShearModuliInSeriesAndInParallel) {
  const Material soft = Material::isotropic("soft", 3000, 0.35);
  const Material stiff = Material::isotropic("stiff", 70000, 0.3);
  const double t1 = 0.4, t2 = 1.1;
  const Matrix6d H = homogenised_stiffness({{soft.stiffness(), t1}, {stiff.stiffness(), t2}});
  const double G1 = 3000 / (2 * 1.35), G2 = 70000 / (2 * 1.3);
  const double series = (t1 + t2) / (t1 / G1 + t2 / G2), parallel = (t1 * G1 + t2 * G2) / (t1 + t2);
  EXPECT_NEAR(H(3, 3), series, 1e-12 * series);  // C44 = G23
  EXPECT_NEAR(H(4, 4), series, 1e-12 * series);  // C55 = G13
  EXPECT_NEAR(H(5, 5), parallel, 1e-12 * parallel);
}

TEST(HomogenisedStiffness, LaminateLayers_SliceKeepsPliesAndCutsPartialOnes) {
  const Laminate lam = make_laminate(paper_material(), kPaperPly, {0, 90, 0, 90, 90, 0, 90, 0});
  const std::vector<LayerStiffness> upper = laminate_layers(lam, 0.0, 1.9);
  ASSERT_EQ(upper.size(), 4u);
  for (const LayerStiffness& l : upper) EXPECT_NEAR(l.thickness, kPaperPly, 1e-14);
  EXPECT_LT((upper[0].C - rotate_stiffness_voigt(paper_material().stiffness(), 90)).norm(),
            1e-9 * upper[0].C.norm());
  const std::vector<LayerStiffness> cut = laminate_layers(lam, -0.2, 0.6);  // in plies 4, 5, 6
  ASSERT_EQ(cut.size(), 3u);
  EXPECT_NEAR(cut[0].thickness, 0.2, 1e-14);
  EXPECT_NEAR(cut[1].thickness, 0.475, 1e-14);
  EXPECT_NEAR(cut[2].thickness, 0.125, 1e-14);
  EXPECT_THROW(laminate_layers(lam, 0.5, 0.2), Error);
}

}  // namespace
}  // namespace si
