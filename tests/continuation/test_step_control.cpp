// Step control and how runs end: growth by Newton iteration count, halving on failure down to
// step_min (then step_too_small with the reason, keeping every converged point), the callback,
// max_steps, a start that does not converge, and Problem::adapt changing the problem's size.
#include <gtest/gtest.h>

#include <cmath>

#include "continuation/natural.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

// F_i = x_i - (i + 1) p on m unknowns: straight branches. With evaluable_below set, the
// residual cannot be evaluated for p above it (as a shell with an inverted element). adapt()
// grows m from 1 to 2 once p passes grow_at, mapping x_1 = 2p.
class LineProblem final : public test::DenseProblem {
 public:
  double evaluable_below = INFINITY;
  double grow_at = INFINITY;

  int size() const override { return m_; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F.resize(m_);
    for (int i = 0; i < m_; ++i) F(i) = x(i) - (i + 1) * p;
    return p <= evaluable_below;
  }
  test::Matrix jacobian(const Vector&, double) const override {
    return test::Matrix::Identity(m_, m_);
  }
  // Analytic: the default central difference would step past evaluable_below near the edge.
  bool residual_p(const Vector&, double, Vector& out) override {
    out = -Vector::LinSpaced(m_, 1.0, m_);
    return true;
  }
  bool adapt(Vector& x, double p) override {
    if (m_ == 2 || p <= grow_at) return false;
    m_ = 2;
    x.conservativeResize(2);
    x(1) = 2.0 * p;
    return true;
  }

 private:
  int m_ = 1;
};

Settings line_settings() {
  Settings s;
  s.step_initial = 0.1;
  s.step_max = 1.0;
  s.p_max = 3.0;
  return s;
}

// The tangent predictor is exact on a straight branch: 0 Newton iterations, so each step grows
// by step_growth_max (2) until step_max (ds *= clamp(target / max(iterations, 1), 1/2, 2)).
TEST(ContStepControl, StepGrowsByGrowthFactorUpToStepMax) {
  LineProblem line;
  const Branch branch = pseudo_arclength(line, Vector::Zero(1), 0.0, line_settings());
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  const double expected[] = {0.1, 0.2, 0.4, 0.8, 1.0, 1.0};
  ASSERT_GE(branch.points.size(), 7u);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(branch.points[i + 1].step, expected[i], 1e-15);
  EXPECT_EQ(branch.points.back().p, 3.0);
}

// Steps that need more Newton iterations than the target shrink: with target_iterations = 1,
// a step taking k >= 2 iterations is followed by one of max(ds / 2, step_min) (factor clamped).
TEST(ContStepControl, StepShrinksWhenNewtonNeedsMoreThanTarget) {
  test::CircleProblem circle;
  Settings s;
  s.step_initial = 0.2;
  s.step_max = 0.2;
  s.target_iterations = 1;
  s.max_steps = 6;
  const Branch branch = pseudo_arclength(circle, Vector::Constant(1, 1.0), 0.0, s);
  ASSERT_EQ(branch.failed_steps, 0);
  int checked = 0;
  for (std::size_t i = 2; i < branch.points.size(); ++i) {
    if (branch.points[i - 1].newton_iterations < 2) continue;
    EXPECT_NEAR(branch.points[i].step, std::max(s.step_min, 0.5 * branch.points[i - 1].step),
                1e-15);
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

TEST(ContStepControl, UnevaluableResidualEndsWithStepTooSmallKeepingPoints) {
  LineProblem line;
  line.evaluable_below = 0.5;
  Settings s = line_settings();
  s.step_min = 1e-6;
  for (const Method method : {Method::kNatural, Method::kPseudoArclength}) {
    s.method = method;
    const Branch branch = method == Method::kNatural
                              ? natural(line, Vector::Zero(1), 0.0, s)
                              : pseudo_arclength(line, Vector::Zero(1), 0.0, s);
    ASSERT_EQ(branch.status, Status::kStepTooSmall) << method_name(method);
    EXPECT_NE(branch.reason.find("cannot be evaluated"), std::string::npos) << branch.reason;
    EXPECT_GT(branch.failed_steps, 0);
    // Halving stops only when a step of step_min fails: the last point is within step_min of
    // the edge (arclength >= |dp| here).
    const double last = branch.points.back().p;
    EXPECT_LE(last, 0.5);
    EXPECT_GE(last, 0.5 - s.step_min);
    for (const auto& pt : branch.points) EXPECT_NEAR(pt.x(0), pt.p, 1e-10);
  }
}

// Each failed step is told as it happens, with the point it started from, its size, the retry
// (half of it, 0 for the last one, of step_min) and the reason; a path without failures tells
// nothing.
TEST(ContStepControl, EachFailedStepIsToldWithItsRetryAndReason) {
  LineProblem line;
  line.evaluable_below = 0.5;
  Settings s = line_settings();
  s.step_min = 1e-6;
  std::vector<StepFailure> told;
  s.on_step_failure = [&](const StepFailure& f) { told.push_back(f); };
  const Branch branch = pseudo_arclength(line, Vector::Zero(1), 0.0, s);
  ASSERT_EQ(branch.status, Status::kStepTooSmall);
  ASSERT_EQ(static_cast<int>(told.size()), branch.failed_steps);
  for (std::size_t i = 0; i + 1 < told.size(); ++i) {
    EXPECT_NEAR(told[i].retry, std::max(0.5 * told[i].step, s.step_min), 1e-15);
    EXPECT_LT(told[i].p, 0.5);
    EXPECT_NE(told[i].reason.find("cannot be evaluated"), std::string::npos) << told[i].reason;
  }
  EXPECT_EQ(told.back().retry, 0.0);
  EXPECT_LE(told.back().step, s.step_min * (1.0 + 1e-12));
  EXPECT_EQ(told.back().p, branch.points.back().p);

  told.clear();
  LineProblem clear;
  const Branch whole = pseudo_arclength(clear, Vector::Zero(1), 0.0, s);
  EXPECT_EQ(whole.failed_steps, 0);
  EXPECT_TRUE(told.empty());
}

TEST(ContStepControl, CallbackStopsKeepingThePoint) {
  LineProblem line;
  const Branch branch =
      pseudo_arclength(line, Vector::Zero(1), 0.0, line_settings(),
                       [](const Point&, const Branch& b) { return b.points.size() < 4; });
  EXPECT_EQ(branch.status, Status::kStoppedByCallback);
  EXPECT_EQ(branch.points.size(), 4u);
  EXPECT_EQ(branch.reason, "stopped by the callback");
}

TEST(ContStepControl, MaxStepsZeroKeepsOnlyTheStart) {
  LineProblem line;
  Settings s = line_settings();
  s.max_steps = 0;
  const Branch branch = pseudo_arclength(line, Vector::Constant(1, 0.3), 0.0, s);
  EXPECT_EQ(branch.status, Status::kMaxSteps);
  ASSERT_EQ(branch.points.size(), 1u);
  EXPECT_NEAR(branch.points[0].x(0), 0.0, 1e-14);  // the start point was corrected
}

TEST(ContStepControl, StartThatDoesNotConvergeIsReported) {
  test::CircleProblem circle;  // no real x with x^2 + 4 = 1
  Settings s;
  s.p_max = 3.0;
  const Branch branch = pseudo_arclength(circle, Vector::Constant(1, 0.5), 2.0, s);
  EXPECT_EQ(branch.status, Status::kStartFailed);
  EXPECT_TRUE(branch.points.empty());
  EXPECT_NE(branch.reason.find("start point"), std::string::npos) << branch.reason;
}

TEST(ContStepControl, StartOutsideBoundsOrWrongSizeRejected) {
  LineProblem line;
  Settings s = line_settings();
  EXPECT_THROW(pseudo_arclength(line, Vector::Zero(1), 4.0, s), std::invalid_argument);
  EXPECT_THROW(pseudo_arclength(line, Vector::Zero(3), 0.0, s), std::invalid_argument);
  s.step_min = 2.0;  // settings are validated first
  EXPECT_THROW(pseudo_arclength(line, Vector::Zero(1), 0.0, s), std::invalid_argument);
}

// adapt() grows the problem at p > 0.45: the run continues in the larger space, with the
// tangent recomputed there, and ends on the bound with x = (p, 2p).
TEST(ContStepControl, AdaptChangesSizeAndTheRunContinues) {
  for (const Predictor predictor : {Predictor::kTangent, Predictor::kSecant}) {
    LineProblem line;
    line.grow_at = 0.45;
    Settings s = line_settings();
    s.predictor = predictor;
    s.step_max = 0.2;
    s.p_max = 1.0;
    const Branch branch = pseudo_arclength(line, Vector::Zero(1), 0.0, s);
    ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
    const Point& last = branch.points.back();
    ASSERT_EQ(last.x.size(), 2);
    EXPECT_NEAR(last.x(0), 1.0, 1e-10);  // corrector tolerance 1e-10 (residual_scale 1)
    EXPECT_NEAR(last.x(1), 2.0, 1e-10);
    // The point that triggered adapt() (the first past grow_at) is replaced by its re-solve in
    // the grown problem: every point past grow_at has two unknowns, the earlier ones one.
    bool grown = false;
    for (const auto& pt : branch.points) {
      EXPECT_EQ(pt.x.size(), pt.p > line.grow_at ? 2 : 1) << "p = " << pt.p;
      grown = grown || pt.p > line.grow_at;
    }
    EXPECT_TRUE(grown);
  }
}

}  // namespace
}  // namespace si::cont
