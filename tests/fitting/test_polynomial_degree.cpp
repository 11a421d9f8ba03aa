// Polynomial degree selection (leave-one-out and AIC) and the interpolation flag.
#include <gtest/gtest.h>

#include <cmath>

#include "fitting/linear_fit.hpp"
#include "fitting/polynomial_degree.hpp"
#include "synthetic_data.hpp"

namespace si::fit {
namespace {

using testing::grid;
using testing::sample;

double cubic(double x) {
  return 1.0 - 2.0 * x + 0.5 * x * x + 0.25 * x * x * x;
}

TEST(PolynomialDegree, ExactCubicChosenByBothCriteria) {
  const Eigen::VectorXd x = grid(-2.0, 3.0, 12);
  const Eigen::VectorXd y = sample(x, cubic, 0.0, 0);
  for (auto criterion :
       {DegreeCriterion::kLeaveOneOut, DegreeCriterion::kAic, DegreeCriterion::kAicc}) {
    const DegreeSelection s = select_polynomial_degree(x, y, 8, criterion);
    EXPECT_EQ(s.chosen_degree, 3) << to_string(criterion);
    ASSERT_EQ(s.scores.size(), 9u);
    EXPECT_EQ(s.scores[8].degree, 8);
  }
}

// With noise the choice is random; over 50 seeds a sound criterion picks the true degree most of
// the time and never an underfitting one (the cubic term is 50 noise levels strong).
TEST(PolynomialDegree, NoisyCubicMostlyChosen) {
  const Eigen::VectorXd x = grid(-2.0, 3.0, 25);
  for (auto criterion :
       {DegreeCriterion::kLeaveOneOut, DegreeCriterion::kAic, DegreeCriterion::kAicc}) {
    int right = 0;
    for (unsigned seed = 1; seed <= 50; ++seed) {
      const auto s = select_polynomial_degree(x, sample(x, cubic, 0.1, seed), 8, criterion);
      EXPECT_GE(s.chosen_degree, 3) << to_string(criterion) << " seed " << seed;
      right += s.chosen_degree == 3;
    }
    EXPECT_GE(right, 35) << to_string(criterion);
  }
}

// LOOCV by the PRESS identity equals refitting without each point.
TEST(PolynomialDegree, LeaveOneOutEqualsExplicitRefits) {
  const Eigen::VectorXd x = grid(0.0, 1.0, 9);
  const Eigen::VectorXd y = sample(x, cubic, 0.05, 7);
  const auto s = select_polynomial_degree(x, y, 2, DegreeCriterion::kLeaveOneOut);
  double press = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    Eigen::VectorXd xi(x.size() - 1), yi(x.size() - 1);
    for (Eigen::Index k = 0, m = 0; k < x.size(); ++k)
      if (k != i) xi[m] = x[k], yi[m++] = y[k];
    const FitResult f = fit_polynomial(xi, yi, 2);
    const double pred = f.parameters[0] + x[i] * (f.parameters[1] + x[i] * f.parameters[2]);
    press += (pred - y[i]) * (pred - y[i]);
  }
  EXPECT_NEAR(s.scores[2].loocv_rmse, std::sqrt(press / x.size()), 1e-12);
}

// Issue 6: a 6th-degree fit through 7 points is flagged as interpolation, and selection never
// offers it.
TEST(PolynomialDegree, SixthDegreeThroughSevenPointsIsInterpolation) {
  const Eigen::VectorXd x = grid(0.0, 6.0, 7);
  const Eigen::VectorXd y = sample(x, cubic, 0.1, 3);
  const FitResult r = fit_polynomial(x, y, 6);
  EXPECT_TRUE(r.interpolation);
  EXPECT_EQ(r.dof, 0);
  EXPECT_TRUE(std::isnan(r.std_errors[0]));
  EXPECT_NE(r.reason.find("interpolation"), std::string::npos) << r.reason;
  EXPECT_FALSE(fit_polynomial(x, y, 5).interpolation);
  EXPECT_THROW(fit_polynomial(x, y, 7), std::invalid_argument);
  const auto s = select_polynomial_degree(x, y, 10, DegreeCriterion::kAic);
  EXPECT_EQ(s.scores.back().degree, 5);
}

// For a straight line with intercept, R^2 is the square of Pearson's r (a property of least
// squares, e.g. Draper & Smith 1998, sec. 1.3).
TEST(PolynomialDegree, StraightLineRSquaredIsPearsonSquared) {
  const Eigen::VectorXd x = grid(0.0, 1.0, 15);
  const FitResult r = fit_polynomial(x, sample(x, cubic, 0.2, 11), 1);
  EXPECT_NEAR(r.r_squared, r.pearson_r * r.pearson_r, 1e-14);
  EXPECT_NEAR(r.rmse, std::sqrt(r.sse / 15), 1e-15);
}

}  // namespace
}  // namespace si::fit
