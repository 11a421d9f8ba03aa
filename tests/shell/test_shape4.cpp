#include "shell/shape4.hpp"

#include <gtest/gtest.h>

namespace si {
namespace {

// Bilinear functions: partition of unity everywhere, nodal interpolation at the corners.
TEST(Shape4, BilinearIsPartitionOfUnity) {
  for (double xi : {-1.0, -0.3, 0.0, 0.7})
    for (double eta : {-1.0, 0.2, 1.0}) {
      const Shape4 s = evaluate_shape4(ShapeSet::kBilinear, xi, eta);
      EXPECT_NEAR(s.N.sum(), 1, 1e-15);
      EXPECT_NEAR(s.N_xi.sum(), 0, 1e-15);
      EXPECT_NEAR(s.N_eta.sum(), 0, 1e-15);
    }
}

// The paper's eqs 68-71: N_I = 1 at its own corner and 0 at the others, but the sum at the centre
// is 4 x 1/64 = 1/16 (paper-notes.md item 1: no partition of unity).
TEST(Shape4, BernsteinSumsToOneSixteenthAtCentre_PaperEqs68to71) {
  for (int i = 0; i < 4; ++i) {
    const Shape4 s = evaluate_shape4(ShapeSet::kBernstein, kCornerXi[i], kCornerEta[i]);
    EXPECT_EQ(s.N, Eigen::Vector4d::Unit(i));
  }
  const Shape4 centre = evaluate_shape4(ShapeSet::kBernstein, 0, 0);
  EXPECT_DOUBLE_EQ(centre.N.sum(), 4.0 / 64);
  EXPECT_NE(evaluate_shape4(ShapeSet::kBernstein, 0.5, 0.2).N_xi.sum(), 0);
}

// Derivatives against central differences, both sets.
TEST(Shape4, DerivativesMatchFiniteDifferences) {
  const double h = 1e-6, xi = 0.31, eta = -0.57;
  for (ShapeSet set : {ShapeSet::kBilinear, ShapeSet::kBernstein}) {
    const Shape4 s = evaluate_shape4(set, xi, eta);
    const Eigen::Vector4d dxi =
        (evaluate_shape4(set, xi + h, eta).N - evaluate_shape4(set, xi - h, eta).N) / (2 * h);
    const Eigen::Vector4d deta =
        (evaluate_shape4(set, xi, eta + h).N - evaluate_shape4(set, xi, eta - h).N) / (2 * h);
    EXPECT_LT((dxi - s.N_xi).norm(), 1e-9);
    EXPECT_LT((deta - s.N_eta).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace si
