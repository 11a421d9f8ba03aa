// The joint confidence ellipsoid and the correlation matrix, against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "fitting/confidence_region.hpp"
#include "fitting/fisher_f.hpp"

namespace si::fit {
namespace {

// A diagonal covariance: the axes are the coordinate axes and the half-lengths sqrt(p F C_jj).
TEST(ConfidenceEllipsoid, DiagonalCovarianceHasCoordinateAxes) {
  const Eigen::Vector2d var(4.0, 0.25);
  const ConfidenceEllipsoid e = confidence_ellipsoid(var.asDiagonal().toDenseMatrix(), 10, 0.95);
  const double pf = 2.0 * fisher_f_quantile(0.95, 2.0, 10.0);
  EXPECT_NEAR(e.half_lengths[0], std::sqrt(pf * 4.0), 1e-12);
  EXPECT_NEAR(e.half_lengths[1], std::sqrt(pf * 0.25), 1e-12);
  EXPECT_NEAR(std::abs(e.axes(0, 0)), 1.0, 1e-12);
  EXPECT_NEAR(e.distance(Eigen::Vector2d::Zero(), Eigen::Vector2d(std::sqrt(pf * 4.0), 0.0)), 1.0,
              1e-12);
  EXPECT_NEAR(e.shadow_half_widths[1], std::sqrt(pf * 0.25), 1e-12);
}

// Correlation of a 2 x 2 covariance [[s1^2, r s1 s2], [r s1 s2, s2^2]] is r; the ellipsoid's
// axes are those of the covariance (eigenvectors) and its boundary point along an axis lies at
// distance 1.
TEST(ConfidenceEllipsoid, CorrelatedCovariance) {
  const double s1 = 3.0, s2 = 0.5, rho = -0.8;
  Eigen::Matrix2d c;
  c << s1 * s1, rho * s1 * s2, rho * s1 * s2, s2 * s2;
  EXPECT_NEAR(correlation_matrix(c)(0, 1), rho, 1e-15);
  const ConfidenceEllipsoid e = confidence_ellipsoid(c, 7, 0.9);
  const Eigen::Vector2d center(1.0, 2.0);
  for (int k = 0; k < 2; ++k)
    EXPECT_NEAR(e.distance(center, center + e.half_lengths[k] * e.axes.col(k)), 1.0, 1e-12);
  EXPECT_THROW(confidence_ellipsoid(c, 0, 0.95), std::invalid_argument);
}

}  // namespace
}  // namespace si::fit
