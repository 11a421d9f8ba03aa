// Problem's defaults: the central finite-difference dF/dp against an analytic one.
#include <gtest/gtest.h>

#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

TEST(ContProblem, ResidualPDefaultFiniteDifferenceMatchesAnalytic) {
  test::CoupledProblem problem(5);
  const Vector x{{0.3, -1.2, 0.8, 2.1, -0.5}};
  for (double p : {0.0, 0.7, -3.0, 40.0}) {
    Vector analytic;
    Vector fd;
    ASSERT_TRUE(problem.residual_p(x, p, analytic));
    ASSERT_TRUE(problem.Problem::residual_p(x, p, fd));
    // Central difference, h = eps^(1/3) max(1,|p|): error ~ h^2 |F_ppp| + eps |F| / h, about
    // 1e-10 relative to the size of F's terms here (p^2 (i + 1) up to 8e3 at p = 40).
    const double scale = 1.0 + p * p * 5.0;
    EXPECT_LT((fd - analytic).lpNorm<Eigen::Infinity>(), 1e-9 * scale) << "p = " << p;
  }
}

TEST(ContProblem, DefaultsAreInert) {
  test::CoupledProblem problem(2);
  Vector x = Vector::Ones(2);
  EXPECT_TRUE(problem.monitor_names().empty());
  EXPECT_EQ(problem.monitors(x, 0.0).size(), 0);
  EXPECT_TRUE(problem.signature(x, 0.0).empty());
  EXPECT_FALSE(problem.adapt(x, 0.0));
  EXPECT_DOUBLE_EQ(problem.inner(Vector{{1.0, 2.0}}, Vector{{3.0, 4.0}}), 11.0);
}

}  // namespace
}  // namespace si::cont
