// F quantiles, which scale the joint confidence region of a calibration.
#include <gtest/gtest.h>

#include <cmath>

#include "fitting/fisher_f.hpp"
#include "fitting/student_t.hpp"

namespace si::fit {
namespace {

// Closed forms: with d1 = 2 the distribution function is 1 - (1 + 2x/d2)^(-d2/2), so the
// p-quantile is (d2/2)((1 - p)^(-2/d2) - 1); and F(1, d) is the square of Student's t with d
// degrees of freedom (Johnson, Kotz & Balakrishnan 1995, ch. 27).
TEST(FisherF, ClosedFormForTwoNumeratorDegrees) {
  for (double d2 : {1.0, 3.0, 10.0, 57.0})
    for (double p : {0.5, 0.9, 0.95, 0.99}) {
      const double exact = 0.5 * d2 * (std::pow(1.0 - p, -2.0 / d2) - 1.0);
      EXPECT_NEAR(fisher_f_quantile(p, 2.0, d2), exact, 1e-10 * exact) << d2 << " " << p;
    }
}

TEST(FisherF, OneNumeratorDegreeIsStudentTSquared) {
  for (double d : {2.0, 5.0, 30.0}) {
    const double t = student_t_quantile(0.975, d);
    EXPECT_NEAR(fisher_f_quantile(0.95, 1.0, d), t * t, 1e-10 * t * t) << d;
  }
}

// Tabulated 95 % points, NIST/SEMATECH e-Handbook of Statistical Methods, sec. 1.3.6.7.3 (upper
// critical values of the F distribution, 3 decimals): F(3, 20) = 3.098, F(5, 10) = 3.326.
TEST(FisherF, QuantilesMatchTables_NistHandbook) {
  EXPECT_NEAR(fisher_f_quantile(0.95, 3.0, 20.0), 3.098, 5e-4);
  EXPECT_NEAR(fisher_f_quantile(0.95, 5.0, 10.0), 3.326, 5e-4);
  EXPECT_DOUBLE_EQ(fisher_f_cdf(0.0, 3.0, 4.0), 0.0);
  EXPECT_THROW(fisher_f_quantile(1.0, 2.0, 2.0), std::invalid_argument);
}

}  // namespace
}  // namespace si::fit
