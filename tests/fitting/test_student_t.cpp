// Student's t quantiles and the incomplete beta function behind them.
#include <gtest/gtest.h>

#include <cmath>

#include "fitting/student_t.hpp"

namespace si::fit {
namespace {

// Closed forms: I_x(1, 1) = x, I_x(a, 1) = x^a, I_x(1, b) = 1 - (1 - x)^b (A&S 26.5.2-26.5.3
// special cases), and the symmetry I_x(a, b) = 1 - I_{1-x}(b, a).
TEST(IncompleteBeta, ClosedFormsAndSymmetry) {
  for (double x : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
    EXPECT_NEAR(incomplete_beta(1.0, 1.0, x), x, 1e-14);
    EXPECT_NEAR(incomplete_beta(3.5, 1.0, x), std::pow(x, 3.5), 1e-14);
    EXPECT_NEAR(incomplete_beta(1.0, 2.5, x), 1.0 - std::pow(1.0 - x, 2.5), 1e-14);
    EXPECT_NEAR(incomplete_beta(2.3, 7.1, x), 1.0 - incomplete_beta(7.1, 2.3, 1.0 - x), 1e-14);
  }
  EXPECT_THROW(incomplete_beta(0.0, 1.0, 0.5), std::invalid_argument);
  EXPECT_THROW(incomplete_beta(1.0, 1.0, 1.5), std::invalid_argument);
}

// t with 1 degree of freedom is Cauchy: P(T <= t) = 1/2 + atan(t)/pi; with 2, t / (2 sqrt(2 + t^2))
// + 1/2 (closed forms of the t distribution, e.g. Johnson, Kotz & Balakrishnan 1995, ch. 28).
TEST(StudentT, CdfClosedFormsForOneAndTwoDegrees) {
  for (double t : {-30.0, -2.0, -0.5, 0.0, 0.3, 1.0, 4.0, 100.0}) {
    EXPECT_NEAR(student_t_cdf(t, 1.0), 0.5 + std::atan(t) / M_PI, 1e-14) << t;
    EXPECT_NEAR(student_t_cdf(t, 2.0), 0.5 + t / (2.0 * std::sqrt(2.0 + t * t)), 1e-14) << t;
  }
}

// Tabulated critical values, NIST/SEMATECH e-Handbook of Statistical Methods, sec. 1.3.6.7.2
// (upper critical values of the t distribution, given to 3 decimals) and the 6-decimal values
// t(0.975, 10) = 2.228139, t(0.975, 30) = 2.042272; the normal limit 1.959964 (A&S 26.2.23).
TEST(StudentT, QuantilesMatchTables_NistHandbook) {
  EXPECT_NEAR(student_t_quantile(0.975, 10), 2.228139, 5e-7);
  EXPECT_NEAR(student_t_quantile(0.975, 30), 2.042272, 5e-7);
  EXPECT_NEAR(student_t_quantile(0.975, 1), 12.706, 5e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 2), 4.303, 5e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 5), 2.571, 5e-4);
  EXPECT_NEAR(student_t_quantile(0.95, 12), 1.782, 5e-4);
  EXPECT_NEAR(student_t_quantile(0.995, 4), 4.604, 5e-4);
  EXPECT_NEAR(student_t_quantile(0.999, 20), 3.552, 5e-4);
  EXPECT_NEAR(student_t_quantile(0.975, 1e7), 1.959964, 5e-6);
  EXPECT_NEAR(student_t_quantile(0.025, 10), -2.228139, 5e-7);
  EXPECT_EQ(student_t_quantile(0.5, 3), 0.0);
}

TEST(StudentT, QuantileInvertsTheCdf) {
  for (double dof : {1.0, 2.5, 7.0, 51.0, 300.0})
    for (double p : {0.6, 0.9, 0.975, 0.999, 0.9999})
      EXPECT_NEAR(student_t_cdf(student_t_quantile(p, dof), dof), p, 1e-13) << dof << " " << p;
  EXPECT_THROW(student_t_quantile(1.0, 3), std::invalid_argument);
  EXPECT_THROW(student_t_quantile(0.9, 0), std::invalid_argument);
}

}  // namespace
}  // namespace si::fit
