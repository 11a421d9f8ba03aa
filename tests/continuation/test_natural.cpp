// Natural-parameter continuation: explicit parameter values hit exactly, bounds, and the end of
// the run at a fold it cannot pass (step_too_small, keeping every converged point).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bratu_problem.hpp"
#include "continuation/natural.hpp"
#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

Settings natural_settings() {
  Settings s;
  s.method = Method::kNatural;
  s.step_initial = 0.1;
  s.step_max = 0.3;
  s.detect_limit_points = false;
  return s;
}

TEST(ContNatural, HitsParameterValuesExactlyAndCompletes) {
  test::CubicBranchProblem problem;
  Settings settings = natural_settings();
  settings.parameter_values = {-1.9, -1.5, 0.25, 1.0 / 3.0, 1.0, 2.3};
  for (const Predictor predictor : {Predictor::kTangent, Predictor::kSecant}) {
    settings.predictor = predictor;
    const Branch branch = natural(problem, Vector::Constant(1, 2.0), -2.0, settings);
    ASSERT_EQ(branch.status, Status::kCompleted) << branch.reason;
    for (double v : settings.parameter_values) {
      const bool hit = std::any_of(branch.points.begin(), branch.points.end(),
                                   [v](const Point& pt) { return pt.p == v; });
      EXPECT_TRUE(hit) << "p = " << v << " was not hit exactly";
    }
    EXPECT_EQ(branch.points.back().p, 2.3);
    for (const auto& pt : branch.points) {
      EXPECT_NEAR(pt.x(0), test::CubicBranchProblem::branch(pt.p), 1e-9);
      EXPECT_LE(pt.step, settings.step_max * (1.0 + 1e-12));  // |dp| after rounding
    }
  }
}

TEST(ContNatural, DirectionMinusOneStopsAtLowerBound) {
  test::CubicBranchProblem problem;
  Settings settings = natural_settings();
  settings.direction = -1;
  settings.p_min = -0.35;
  const Branch branch = natural(problem, Vector::Constant(1, 0.0), 0.0, settings);
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  EXPECT_EQ(branch.points.back().p, -0.35);
  for (std::size_t i = 1; i < branch.points.size(); ++i)
    EXPECT_LT(branch.points[i].p, branch.points[i - 1].p);
}

TEST(ContNatural, StartOnTheBoundAheadEndsAtOnce) {
  test::CubicBranchProblem problem;
  Settings settings = natural_settings();
  settings.p_max = 0.5;
  const Branch branch = natural(problem, Vector::Constant(1, 0.0), 0.5, settings);
  EXPECT_EQ(branch.status, Status::kReachedBound);
  EXPECT_EQ(branch.points.size(), 1u);
}

TEST(ContNatural, ParameterValueBehindStartRejected) {
  test::CubicBranchProblem problem;
  Settings settings = natural_settings();
  settings.parameter_values = {-3.0, 1.0};
  EXPECT_THROW(natural(problem, Vector::Constant(1, 2.0), -2.0, settings), std::invalid_argument);
}

// Natural continuation in lambda cannot pass the Bratu fold (lambda_c(h) = 3.51379 for n = 200,
// test_pseudo_arclength.cpp): the run ends with step_too_small, every point before it kept.
TEST(ContNatural, BratuFoldEndsWithStepTooSmallKeepingConvergedPoints) {
  const int n = 200;
  test::BratuProblem bratu(n);
  Settings settings = natural_settings();
  settings.step_max = 0.5;
  settings.step_min = 1e-4;
  settings.p_max = 5.0;
  settings.newton.residual_scale = 10.0;
  const Branch branch = natural(bratu, Vector::Zero(n), 0.0, settings);
  ASSERT_EQ(branch.status, Status::kStepTooSmall);
  EXPECT_NE(branch.reason.find("failed"), std::string::npos) << branch.reason;
  EXPECT_GT(branch.failed_steps, 0);
  const double last = branch.points.back().p;
  EXPECT_LT(last, 3.5137855);  // below the discrete fold
  EXPECT_GT(last, 3.40);       // and it got close to it
  for (const auto& pt : branch.points) {
    Vector F;
    bratu.residual(pt.x, pt.p, F);
    EXPECT_LT(F.lpNorm<Eigen::Infinity>(), 1e-9);  // every kept point converged (tol 1e-10 * 10)
  }
}

}  // namespace
}  // namespace si::cont
