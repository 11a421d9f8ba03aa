// The nonlinear fitter's contract: bounds, argument checks, evaluation counts, problems without
// observations, and the Jacobian by finite differences against the analytic one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "fitting/builtin_models.hpp"
#include "fitting/nonlinear_fit.hpp"
#include "synthetic_data.hpp"

namespace si::fit {
namespace {

using testing::grid;
using testing::sample;

double curve(double x) {
  return 350.0 * std::pow(x, 1.37);
}

TEST(NonlinearFit, BoundStopsTheExponentAndIsReported) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 20);
  FitSettings s;
  s.start = Eigen::Vector2d(100.0, 1.0);
  s.lower = Eigen::Vector2d(0.0, 0.5);
  s.upper = Eigen::Vector2d(1e4, 1.2);  // the true exponent 1.37 is outside
  const FitResult r = fit_curve(power_law(), x, sample(x, curve, 0.0, 0), s);
  EXPECT_EQ(r.status, FitStatus::kConverged) << r.reason;  // a bound-constrained minimum
  EXPECT_DOUBLE_EQ(r.parameters[1], 1.2);
  EXPECT_TRUE(r.at_bound[1]);
  EXPECT_FALSE(r.at_bound[0]);
}

// Exact data rounded to 12 digits (as a CSV file carries them): the residuals are rounding noise,
// no step decreases S any more, and the fit must still report convergence.
TEST(NonlinearFit, DataRoundedTo12DigitsConverges) {
  const Eigen::VectorXd x = grid(0.2, 2.0, 19);
  for (const double offset : {3.0, 0.0}) {  // 0: a parameter whose value is rounding noise
    Eigen::VectorXd y(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.12g", 350.0 * std::pow(x[i], 1.37) + offset);
      y[i] = std::stod(buf);
    }
    const FitResult r = fit_curve(power_law_with_offset(), x, y);
    EXPECT_EQ(r.status, FitStatus::kConverged) << offset << ": " << r.reason;
    EXPECT_NEAR(r.parameters[1], 1.37, 1e-8);
  }
}

TEST(NonlinearFit, RejectsInconsistentSettings) {
  const auto p = curve_problem(power_law(), grid(0.1, 2.0, 10), grid(1.0, 5.0, 10));
  FitSettings s;
  EXPECT_THROW(fit(p, s), std::invalid_argument);  // no start
  s.start = Eigen::Vector2d(1.0, 1.0);
  s.lower = Eigen::Vector2d(2.0, 0.0);
  EXPECT_THROW(fit(p, s), std::invalid_argument);  // start below its bound
  s.lower = Eigen::Vector3d(0.0, 0.0, 0.0);
  EXPECT_THROW(fit(p, s), std::invalid_argument);  // bounds of the wrong size
  s.lower.resize(0);
  s.start = Eigen::Vector2d(1.0, -1.0);
  const auto at_zero = curve_problem(power_law(), grid(0.0, 2.0, 10), grid(1.0, 5.0, 10));
  EXPECT_THROW(fit(at_zero, s), std::invalid_argument);  // 0^-1: residuals not finite
  const auto one_point = curve_problem(power_law(), grid(1.0, 1.0, 1), grid(1.0, 1.0, 1));
  s.start = Eigen::Vector2d(1.0, 1.0);
  EXPECT_THROW(fit(one_point, s), std::invalid_argument);  // 2 parameters, 1 point
}

// A problem given by residuals only (no observations, no Jacobian): the Rosenbrock function as
// least squares, r = (10 (c2 - c1^2), 1 - c1), minimum (1, 1) with zero residual.
TEST(NonlinearFit, ResidualsOnlyProblem_Rosenbrock) {
  LeastSquaresProblem p;
  p.num_residuals = 2;
  p.parameter_names = {"c1", "c2"};
  p.residuals = [](const Eigen::VectorXd& c, Eigen::VectorXd& r) {
    r << 10.0 * (c[1] - c[0] * c[0]), 1.0 - c[0];
  };
  FitSettings s;
  s.start = Eigen::Vector2d(-1.2, 1.0);
  const FitResult r = fit(p, s);
  EXPECT_EQ(r.status, FitStatus::kConverged) << r.reason;
  EXPECT_NEAR(r.parameters[0], 1.0, 1e-10);
  EXPECT_NEAR(r.parameters[1], 1.0, 1e-10);
  EXPECT_TRUE(r.interpolation);  // 2 parameters, 2 residuals
  EXPECT_TRUE(std::isnan(r.r_squared));
  EXPECT_TRUE(r.evaluations.finite_differences);
  EXPECT_GT(r.evaluations.residuals, 0);
  EXPECT_GT(r.evaluations.jacobians, 0);
}

TEST(NonlinearFit, FiniteDifferenceJacobianMatchesAnalytic) {
  const Eigen::VectorXd x = grid(0.0, 2.0, 9);
  const CurveModel model = power_law();
  const auto analytic = curve_problem(model, x, sample(x, curve, 0.0, 0));
  auto numeric = analytic;
  numeric.jacobian = nullptr;
  const Eigen::Vector2d c(300.0, 1.5);
  Evaluator ea(analytic, c), en(numeric, c);
  const Eigen::MatrixXd ja = ea.jacobian(c);
  // Central differences with h = eps^(1/3) |c|: relative error ~ eps^(2/3) ~ 4e-11.
  EXPECT_LT((en.jacobian(c) - ja).norm() / ja.norm(), 1e-9);
  EXPECT_EQ(en.counts().residuals, 4);
}

}  // namespace
}  // namespace si::fit
