// The least-squares patch fit of nodal fields (model/patch_fit.hpp): exact for polynomials of its
// degree on irregular nodes, convergent on a smooth field (the Navier plate's sin-sin mode) at the
// orders a cubic fit allows, and refusing what it cannot do.
#include "model/patch_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace si {
namespace {

// f = 1 + 2x - y + 3x^2 - xy + 0.5 y^2 + 0.7 x^3 - 1.1 x^2 y + 0.4 x y^2 + 2 y^3 and its
// derivatives at (x, y).
struct Cubic {
  static double f(double x, double y) {
    return 1 + 2 * x - y + 3 * x * x - x * y + 0.5 * y * y + 0.7 * x * x * x - 1.1 * x * x * y +
           0.4 * x * y * y + 2 * y * y * y;
  }
};

TEST(PatchFit, CubicIsReproducedExactlyOnIrregularNodes) {
  std::vector<Vector2d> points;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)  // a perturbed grid
      points.emplace_back(0.3 * i + 0.05 * std::sin(3.1 * j + i), 0.3 * j + 0.04 * std::cos(i));
  Eigen::MatrixXd values(points.size(), 2);
  for (size_t k = 0; k < points.size(); ++k) {
    values(k, 0) = Cubic::f(points[k].x(), points[k].y());
    values(k, 1) = -2 * values(k, 0);
  }
  const double x = 0.95, y = 1.02;
  const PatchFit fit = fit_patch(points, values, Vector2d(x, y), 3, 25);
  EXPECT_EQ(fit.nodes, 25);
  EXPECT_NEAR(fit.value(0), Cubic::f(x, y), 1e-11);
  EXPECT_NEAR(fit.value(1), -2 * Cubic::f(x, y), 1e-11);
  EXPECT_NEAR(fit.d1[0](0), 2 + 6 * x - y + 2.1 * x * x - 2.2 * x * y + 0.4 * y * y, 1e-10);
  EXPECT_NEAR(fit.d1[1](0), -1 - x + y - 1.1 * x * x + 0.8 * x * y + 6 * y * y, 1e-10);
  EXPECT_NEAR(fit.d2[0](0), 6 + 4.2 * x - 2.2 * y, 1e-9);
  EXPECT_NEAR(fit.d2[1](0), -1 - 2.2 * x + 0.8 * y, 1e-9);
  EXPECT_NEAR(fit.d2[2](0), 1 + 0.8 * x + 12 * y, 1e-9);
  EXPECT_NEAR(fit.d3[0](0), 4.2, 1e-8);
  EXPECT_NEAR(fit.d3[1](0), -2.2, 1e-8);
  EXPECT_NEAR(fit.d3[2](0), 0.8, 1e-8);
  EXPECT_NEAR(fit.d3[3](0), 12, 1e-8);
}

// sin(pi x) sin(pi y) on [0, 1]^2 sampled on n x n grids, derivatives at the grid node
// (0.375, 0.5625), whose 25 nearest nodes are the centred 5 x 5 block: there the odd terms of the
// fit's truncation error cancel, so a cubic fit has first- and third-derivative errors O(h^4) and
// O(h^2) (halving the spacing divides them by about 16 and 4), and second derivatives O(h^2).
TEST(PatchFit, SmoothFieldConvergesAtTheFitsOrder) {
  const double pi = std::acos(-1.0), x = 0.375, y = 0.5625;
  double previous[4] = {0, 0, 0, 0};
  for (int n : {16, 32, 64}) {
    std::vector<Vector2d> points;
    Eigen::MatrixXd values((n + 1) * (n + 1), 1);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        points.emplace_back(double(i) / n, double(j) / n);
        values(points.size() - 1, 0) = std::sin(pi * i / n) * std::sin(pi * j / n);
      }
    const PatchFit fit = fit_patch(points, values, Vector2d(x, y), 3, 25);
    const double sx = std::sin(pi * x), cx = std::cos(pi * x), sy = std::sin(pi * y),
                 cy = std::cos(pi * y);
    const double error[4] = {std::abs(fit.value(0) - sx * sy),
                             std::abs(fit.d1[0](0) - pi * cx * sy),
                             std::abs(fit.d2[1](0) - pi * pi * cx * cy),
                             std::abs(fit.d3[0](0) + pi * pi * pi * cx * sy)};
    std::printf("n %d: errors value %.2e, d1 %.2e, d2 %.2e, d3 %.2e\n", n, error[0], error[1],
                error[2], error[3]);
    EXPECT_LT(error[3], 0.05 * pi * pi * pi);
    if (previous[0] > 0) {
      EXPECT_GT(previous[1] / error[1], 12.0) << n;
      EXPECT_GT(previous[2] / error[2], 3.5) << n;
      EXPECT_GT(previous[3] / error[3], 3.5) << n;
    }
    for (int k = 0; k < 4; ++k) previous[k] = error[k];
  }
}

TEST(PatchFit, RefusesWhatItCannotFit) {
  std::vector<Vector2d> line;
  for (int i = 0; i < 30; ++i) line.emplace_back(0.1 * i, 0.2 * i);
  const Eigen::MatrixXd values = Eigen::MatrixXd::Ones(30, 1);
  EXPECT_THROW(fit_patch(line, values, Vector2d(1, 2), 2), Error);      // aligned
  EXPECT_THROW(fit_patch(line, values, Vector2d(1, 2), 0), Error);      // degree
  EXPECT_THROW(fit_patch(line, values, Vector2d(1, 2), 4, 40), Error);  // too few nodes
  EXPECT_THROW(fit_patch(line, Eigen::MatrixXd::Ones(29, 1), Vector2d(1, 2), 1), Error);
}

}  // namespace
}  // namespace si
