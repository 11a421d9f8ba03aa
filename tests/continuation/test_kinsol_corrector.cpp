// The KINSOL corrector on its own (solve_at at a fixed parameter).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "continuation/kinsol_corrector.hpp"
#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

NewtonSettings tight_settings() {
  NewtonSettings s;
  s.relative_tolerance = 1e-13;
  s.residual_scale = 0.0;
  return s;
}

// Observed order of convergence from three successive residual norms.
double observed_order(double r0, double r1, double r2) {
  return std::log(r2 / r1) / std::log(r1 / r0);
}

// Newton's method converges quadratically near a regular root (Dennis & Schnabel 1996,
// Thm 5.2.1): the observed order log(r_{k+1}/r_k) / log(r_k/r_{k-1}) tends to 2.
void expect_quadratic(bool line_search) {
  test::CoupledProblem problem(4);
  const double p = 1.0;
  Vector x = Vector::Constant(4, 1.2);
  NewtonSettings settings = tight_settings();
  settings.line_search = line_search;
  const NewtonResult result = solve_at(problem, x, p, settings);
  ASSERT_TRUE(result.converged) << result.reason;
  EXPECT_EQ(result.flag_name, "KIN_SUCCESS");
  EXPECT_LE(result.iterations, 10);
  Vector F;
  problem.residual(x, p, F);
  EXPECT_LE(F.lpNorm<Eigen::Infinity>(), result.tolerance);

  const auto& r = result.residual_norms;
  ASSERT_EQ(static_cast<int>(r.size()), result.iterations + 1);
  // Best order over the iterates still above roundoff (1e-12 here: F's terms are O(1-10)).
  double best = 0.0;
  for (std::size_t k = 2; k < r.size(); ++k)
    if (r[k] > 1e-12 && r[k - 1] < 1e-1)
      best = std::max(best, observed_order(r[k - 2], r[k - 1], r[k]));
  EXPECT_GT(best, 1.8) << "residual history does not show quadratic convergence";
}

TEST(ContKinsolCorrector, QuadraticConvergenceWithLineSearch) {
  expect_quadratic(true);
}

TEST(ContKinsolCorrector, QuadraticConvergenceWithoutLineSearch) {
  expect_quadratic(false);
}

TEST(ContKinsolCorrector, ExactStartNeedsNoIteration) {
  test::CircleProblem circle;
  Vector x{{0.6}};
  const NewtonResult result = solve_at(circle, x, 0.8, tight_settings());
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.iterations, 0);
}

// x^2 + p^2 = 1 has no real root at p = 2: the solve fails with a reason, quietly.
TEST(ContKinsolCorrector, NoRootFailsWithReasonAndNoStderr) {
  test::CircleProblem circle;
  Vector x{{0.5}};
  NewtonSettings settings = tight_settings();
  settings.max_iterations = 30;
  testing::internal::CaptureStderr();
  const NewtonResult result = solve_at(circle, x, 2.0, settings);
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_FALSE(result.converged);
  EXPECT_FALSE(result.reason.empty());
  EXPECT_NE(result.flag_name, "KIN_SUCCESS");
  EXPECT_TRUE(err.empty()) << "stderr: " << err;
}

// F = (x0 - 1, x1^2 + 1 + p): the second has no real root, the first converges. The failure
// names where the residual is largest, in the problem's words (Problem::unknown_name).
class NoRootInTheSecond final : public test::DenseProblem {
 public:
  int size() const override { return 2; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F = Vector{{x(0) - 1.0, x(1) * x(1) + 1.0 + p}};
    return true;
  }
  test::Matrix jacobian(const Vector& x, double) const override {
    return test::Matrix{{1.0, 0.0}, {0.0, 2.0 * x(1)}};
  }
  std::string unknown_name(int i) const override { return i == 1 ? "the second" : "the first"; }
};

TEST(ContKinsolCorrector, FailureNamesWhereTheResidualIsLargest) {
  NoRootInTheSecond problem;
  Vector x{{0.0, 0.5}};
  NewtonSettings settings = tight_settings();
  settings.max_iterations = 30;
  const NewtonResult result = solve_at(problem, x, 0.0, settings);
  EXPECT_FALSE(result.converged);
  EXPECT_NE(result.reason.find("largest at unknown 1 (the second)"), std::string::npos)
      << result.reason;
}

// F = x^2 + 3 has no real root: the line search creeps towards x = 0, where ||F|| has its
// non-zero minimum. With stall_window the corrector gives up once two iterations have cut
// ||F||_2 by less than 10 %, long before max_iterations, and says so. (One unknown: ||F||_2 is
// the ||F||_inf the history holds.)
TEST(ContKinsolCorrector, StalledResidualGivesUpEarlyAndSaysWhy) {
  test::CircleProblem circle;  // x^2 + p^2 - 1
  NewtonSettings settings = tight_settings();
  settings.max_iterations = 40;
  Vector x{{0.5}};
  const NewtonResult creeping = solve_at(circle, x, 2.0, settings);
  ASSERT_FALSE(creeping.converged);
  settings.stall_window = 2;
  Vector y{{0.5}};
  const NewtonResult stalled = solve_at(circle, y, 2.0, settings);
  ASSERT_FALSE(stalled.converged);
  EXPECT_LT(stalled.iterations, creeping.iterations);
  EXPECT_NE(stalled.reason.find("the residual stalled"), std::string::npos) << stalled.reason;
  // The history ends where it gave up, one entry per iteration and the start, and its last two
  // iterations fell by less than the factor 0.9.
  const auto& r = stalled.residual_norms;
  ASSERT_EQ(static_cast<int>(r.size()), stalled.iterations + 1);
  ASSERT_GE(r.size(), 3u);
  EXPECT_GT(r.back(), 0.9 * r[r.size() - 3]);
}

// F = (x0 + c (x1^2 + x2^2 + x3^2), x1, x2, x3) from (-3c, 1, 1, 1), c = 1/2: the first Newton
// step solves the last three rows and moves their error onto the first, F = (0, 1, 1, 1) ->
// (1.5, 0, 0, 0) (||F||_inf up by 1.5, ||F||_2 down by 0.87), and the second converges. Watched on
// ||F||_2, as KINSOL's line search is, the step is progress, not a stall, even with a window of 1
// (the D7136 plate's support frame did this on the way to converging: docs/performance.md).
class ErrorMovesToOneRow final : public test::DenseProblem {
 public:
  int size() const override { return 4; }
  bool residual(const Vector& x, double, Vector& F) override {
    F = x;
    F(0) += kC * x.tail(3).squaredNorm();
    return true;
  }
  test::Matrix jacobian(const Vector& x, double) const override {
    test::Matrix J = test::Matrix::Identity(4, 4);
    J.block(0, 1, 1, 3) = 2.0 * kC * x.tail(3).transpose();
    return J;
  }
  static constexpr double kC = 0.5;
};

TEST(ContKinsolCorrector, InfNormRisingWhileTheTwoNormFallsIsNotAStall) {
  ErrorMovesToOneRow problem;
  NewtonSettings settings = tight_settings();
  settings.stall_window = 1;
  Vector x{{-3.0 * ErrorMovesToOneRow::kC, 1.0, 1.0, 1.0}};
  const NewtonResult result = solve_at(problem, x, 0.0, settings);
  ASSERT_TRUE(result.converged) << result.reason;
  ASSERT_GE(result.residual_norms.size(), 2u);
  EXPECT_GT(result.residual_norms[1], result.residual_norms[0]);  // the rise it must tolerate
}

// x^3 = 0: Newton converges linearly (x shrinks by 2/3, ||F|| by 8/27 per iteration) towards the
// triple root, slow but steady. The stall rule must not cut it.
class TripleRoot final : public test::DenseProblem {
 public:
  int size() const override { return 1; }
  bool residual(const Vector& x, double, Vector& F) override {
    F = Vector::Constant(1, x(0) * x(0) * x(0));
    return true;
  }
  test::Matrix jacobian(const Vector& x, double) const override {
    return test::Matrix::Constant(1, 1, 3.0 * x(0) * x(0));
  }
};

TEST(ContKinsolCorrector, SlowButSteadyConvergenceIsNotAStall) {
  TripleRoot problem;
  NewtonSettings settings = tight_settings();
  settings.relative_tolerance = 1e-8;
  settings.max_iterations = 40;
  settings.stall_window = 2;
  Vector x{{1.0}};
  const NewtonResult result = solve_at(problem, x, 0.0, settings);
  EXPECT_TRUE(result.converged) << result.reason;
  EXPECT_GE(result.iterations, 10);  // 16 at 8/27 per iteration: a long run, not cut
}

// A residual that cannot be evaluated is a recoverable failure, reported, not thrown.
class Unevaluable final : public test::DenseProblem {
 public:
  int size() const override { return 1; }
  bool residual(const Vector& x, double, Vector& F) override {
    F = Vector::Constant(1, x(0) - 1.0);
    return x(0) < 0.5;  // the root x = 1 is out of reach
  }
  test::Matrix jacobian(const Vector&, double) const override { return test::Matrix::Ones(1, 1); }
};

TEST(ContKinsolCorrector, UnevaluableResidualIsAFailureNotAThrow) {
  Unevaluable problem;
  Vector x{{0.0}};
  testing::internal::CaptureStderr();
  NewtonResult result;
  EXPECT_NO_THROW(result = solve_at(problem, x, 0.0, tight_settings()));
  testing::internal::GetCapturedStderr();
  EXPECT_FALSE(result.converged);
  EXPECT_FALSE(result.reason.empty());
  Vector y{{3.0}};
  result = solve_at(problem, y, 0.0, tight_settings());
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.reason, "the residual cannot be evaluated at the starting point");
}

// A factorization that fails says why: the problem's own reason (Problem::failure) reaches the
// corrector's, ahead of KINSOL's generic "the Jacobian routine failed".
class UnfactorableAbove final : public test::DenseProblem {
 public:
  int size() const override { return 1; }
  bool residual(const Vector& x, double, Vector& F) override {
    F = Vector::Constant(1, x(0) * x(0) - 4.0);
    return true;
  }
  test::Matrix jacobian(const Vector& x, double) const override {
    return test::Matrix::Constant(1, 1, 2.0 * x(0));
  }
  bool factorize(const Vector& x, double p) override {
    if (x(0) > 1.5) return test::DenseProblem::factorize(x, p);
    failed_at_ = x(0);
    return false;
  }
  std::string failure() const override {
    return "the test's factor refused x = " + std::to_string(failed_at_);
  }

 private:
  double failed_at_ = 0.0;
};

TEST(ContKinsolCorrector, FailedFactorizationReasonReachesTheResult) {
  UnfactorableAbove problem;
  Vector x{{1.0}};
  const NewtonResult result = solve_at(problem, x, 0.0, tight_settings());
  EXPECT_FALSE(result.converged);
  EXPECT_NE(result.reason.find("the Jacobian's set-up failed: the test's factor refused x = 1.0"),
            std::string::npos)
      << result.reason;
  Vector y{{3.0}};  // factorable all the way to the root x = 2: no failure, no reason
  const NewtonResult fine = solve_at(problem, y, 0.0, tight_settings());
  EXPECT_TRUE(fine.converged) << fine.reason;
  EXPECT_TRUE(fine.reason.empty());
}

TEST(ContKinsolCorrector, SizeMismatchThrows) {
  test::CoupledProblem problem(3);
  Vector x = Vector::Zero(2);
  EXPECT_THROW(solve_at(problem, x, 0.0, tight_settings()), std::invalid_argument);
}

}  // namespace
}  // namespace si::cont
