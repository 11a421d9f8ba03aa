// Problem::corrector_start: a problem's own start for a step's fixed-parameter corrector (e.g. an
// indentation path's first step from a simpler model's solution). The steppers try it first and
// fall back to their predictor when the corrector fails from it or ends off the step; the points
// are the branch's either way, and the iterations of both correctors count.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "continuation/natural.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

// x^2 = 1 + p: two branches x = +-sqrt(1 + p); the run follows x = +sqrt(1 + p) from (1, 0).
// Offers `start(p)` for the step out of p = 0 (none elsewhere); residual() refuses |x| > 100
// (a start from which the corrector cannot even evaluate).
class TwoRootProblem final : public test::DenseProblem {
 public:
  explicit TwoRootProblem(std::function<double(double)> start) : start_(std::move(start)) {}
  int asked = 0;  // corrector_start calls that offered a start
  int size() const override { return 1; }
  bool residual(const Vector& x, double p, Vector& F) override {
    if (std::abs(x(0)) > 100.0) return false;
    F = Vector::Constant(1, x(0) * x(0) - 1.0 - p);
    return true;
  }
  test::Matrix jacobian(const Vector& x, double) const override {
    return test::Matrix::Constant(1, 1, 2.0 * x(0));
  }
  bool residual_p(const Vector&, double, Vector& out) override {
    out = Vector::Constant(1, -1.0);
    return true;
  }
  Vector corrector_start(const Vector&, double p_from, double p) override {
    if (!start_ || p_from != 0.0) return {};
    ++asked;
    return Vector::Constant(1, start_(p));
  }
  static double branch(double p) { return std::sqrt(1.0 + p); }

 private:
  std::function<double(double)> start_;
};

Settings settings_for(Method method) {
  Settings s;
  s.method = method;
  s.step_initial = 0.8;
  s.step_max = 0.8;
  s.target_iterations = 100;  // the step stays 0.8: the runs compared take the same steps
  s.p_max = 4.0;
  s.natural_corrector_slope = 0.1;  // pseudo-arclength corrects at fixed p (the branch is steep)
  s.newton.residual_scale = 1e-3;
  s.detect_signature_changes = false;
  return s;
}

Branch trace(TwoRootProblem& problem, Method method) {
  const Settings s = settings_for(method);
  return method == Method::kNatural ? natural(problem, Vector::Ones(1), 0.0, s)
                                    : pseudo_arclength(problem, Vector::Ones(1), 0.0, s);
}

class CorrectorStart : public ::testing::TestWithParam<Method> {};

// The exact solution as the start: the first step converges where it starts (no iteration),
// against several from the tangent predictor. Natural continuation takes the same steps either
// way; pseudo-arclength corrects its first step at the predictor's p instead of along the
// arclength (the points differ, both on the branch).
TEST_P(CorrectorStart, AnExactStartSavesTheFirstStepsIterations) {
  TwoRootProblem plain(nullptr);
  TwoRootProblem started([](double p) { return TwoRootProblem::branch(p); });
  const Branch a = trace(plain, GetParam());
  const Branch b = trace(started, GetParam());
  ASSERT_EQ(a.status, Status::kReachedBound) << a.reason;
  ASSERT_EQ(b.status, Status::kReachedBound) << b.reason;
  EXPECT_GE(a.points[1].newton_iterations, 2);
  EXPECT_EQ(b.points[1].newton_iterations, 0);
  EXPECT_EQ(started.asked, 1);
  for (const Point& pt : b.points) EXPECT_NEAR(pt.x(0), TwoRootProblem::branch(pt.p), 1e-9);
  if (GetParam() == Method::kNatural) {
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 1; i < a.points.size(); ++i) {
      EXPECT_EQ(b.points[i].p, a.points[i].p);
      if (i > 1) {
        EXPECT_EQ(b.points[i].newton_iterations, a.points[i].newton_iterations);
      }
    }
  }
}

// The step control reads the iterations as the predictor's error: after a step corrected from
// the problem's own start (no iteration here) the next step keeps its size, where the same run
// from the predictor grows it.
TEST_P(CorrectorStart, AStepFromTheProblemsStartDoesNotGrowTheNext) {
  Settings s = settings_for(GetParam());
  s.target_iterations = 4;
  s.step_max = 10.0;
  TwoRootProblem plain(nullptr);
  TwoRootProblem started([](double p) { return TwoRootProblem::branch(p); });
  const Vector x0 = Vector::Ones(1);
  const bool natural_method = GetParam() == Method::kNatural;
  const Branch a =
      natural_method ? natural(plain, x0, 0.0, s) : pseudo_arclength(plain, x0, 0.0, s);
  const Branch b =
      natural_method ? natural(started, x0, 0.0, s) : pseudo_arclength(started, x0, 0.0, s);
  ASSERT_GE(a.points.size(), 3u);
  ASSERT_GE(b.points.size(), 3u);
  ASSERT_LT(a.points[1].newton_iterations, 4);
  EXPECT_GT(a.points[2].step, 1.2 * a.points[1].step);
  EXPECT_EQ(b.points[1].newton_iterations, 0);
  // (pseudo-arclength: the step is measured along the predictor's direction after a fixed-p
  // correction, within a few percent of the nominal size)
  EXPECT_LE(b.points[2].step, 1.05 * b.points[1].step);
}

// A start from which the corrector cannot evaluate: the predictor's corrector takes over, and the
// run stays on its branch.
TEST_P(CorrectorStart, AStartThatFailsFallsBackToThePredictor) {
  TwoRootProblem bad([](double) { return 1e6; });
  const Branch b = trace(bad, GetParam());
  ASSERT_EQ(b.status, Status::kReachedBound) << b.reason;
  for (const Point& pt : b.points) EXPECT_NEAR(pt.x(0), TwoRootProblem::branch(pt.p), 1e-9);
  EXPECT_EQ(b.failed_steps, 0);
  EXPECT_GE(bad.asked, 1);
}

// A start on the other branch (x = -sqrt(1 + p)): the corrector converges there, but the point is
// behind the step's direction; the pseudo-arclength stepper rejects it and stays on its branch.
TEST(CorrectorStartArclength, AStartOnAnotherBranchIsNotTaken) {
  TwoRootProblem other([](double p) { return -TwoRootProblem::branch(p); });
  const Branch b = trace(other, Method::kPseudoArclength);
  ASSERT_EQ(b.status, Status::kReachedBound) << b.reason;
  for (const Point& pt : b.points) EXPECT_NEAR(pt.x(0), TwoRootProblem::branch(pt.p), 1e-9);
  EXPECT_GE(other.asked, 1);
}

INSTANTIATE_TEST_SUITE_P(Steppers, CorrectorStart,
                         ::testing::Values(Method::kNatural, Method::kPseudoArclength));

}  // namespace
}  // namespace si::cont
