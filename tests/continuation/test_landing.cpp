// Landing on targets: a pseudo-arclength step that would pass p_max, p_min or a
// Settings::parameter_values entry is shortened to reach it (predictor to p = target along the
// tangent, corrector at that fixed p), so the point lies on the target exactly and costs what an
// ordinary step costs: no overshoot followed by a located re-solve. Folds of p are passed as
// before (Keller's step there).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "continuation/natural.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

// x^3 + x = p: one smooth branch, monotone in p, nonlinear (Newton takes several iterations).
// Counts its residual evaluations and factorizations.
class CountingCubic final : public test::DenseProblem {
 public:
  int residuals = 0;
  int size() const override { return 1; }
  bool residual(const Vector& x, double p, Vector& F) override {
    ++residuals;
    F = Vector::Constant(1, x(0) * x(0) * x(0) + x(0) - p);
    return true;
  }
  test::Matrix jacobian(const Vector& x, double) const override {
    return test::Matrix::Constant(1, 1, 3.0 * x(0) * x(0) + 1.0);
  }
  bool residual_p(const Vector&, double, Vector& out) override {
    out = Vector::Constant(1, -1.0);
    return true;
  }
  // The branch in closed form (Cardano): the real root of x^3 + x - p.
  static double branch(double p) {
    const double r = std::sqrt(p * p / 4.0 + 1.0 / 27.0);
    return std::cbrt(p / 2.0 + r) + std::cbrt(p / 2.0 - r);
  }
};

Settings cubic_settings(double p_max) {
  Settings s;
  s.step_initial = 0.3;
  s.step_max = 0.7;
  s.p_max = p_max;
  s.detect_signature_changes = false;
  return s;
}

// Work of each accepted step beyond its Newton iterations, read at the callback.
struct StepWork {
  int iterations = 0;
  int factorizations = 0;
  int residuals = 0;
};

std::vector<StepWork> work_per_step(const Branch& branch, const std::vector<StepWork>& totals) {
  std::vector<StepWork> steps;
  for (std::size_t i = 1; i < totals.size(); ++i)
    steps.push_back({branch.points[i].newton_iterations,
                     totals[i].factorizations - totals[i - 1].factorizations,
                     totals[i].residuals - totals[i - 1].residuals});
  return steps;
}

// The last point is on p_max exactly, on the closed-form branch, for bounds that fall anywhere
// within a step.
TEST(ContLanding, LastPointIsExactlyOnTheBound) {
  for (double p_max : {0.5, 1.0 / 3.0, 2.0, 7.25, 10.0}) {
    CountingCubic cubic;
    const Branch branch = pseudo_arclength(cubic, Vector::Zero(1), 0.0, cubic_settings(p_max));
    ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
    EXPECT_EQ(branch.points.back().p, p_max);
    EXPECT_NEAR(branch.points.back().x(0), CountingCubic::branch(p_max), 1e-10);
    EXPECT_EQ(branch.failed_steps, 0);
  }
}

// The landing step costs an ordinary step: per accepted step, the factorizations and residual
// evaluations beyond its Newton iterations are the same for every step, the last included
// (the old overshoot located the bound by regula falsi on the segment and solved there again:
// 3-4.6 times an ordinary step on the paper's cap).
TEST(ContLanding, LandingCostsNoExtraSolve) {
  CountingCubic cubic;
  std::vector<StepWork> totals;
  const Callback record = [&](const Point&, const Branch&) {
    totals.push_back({0, cubic.factorizations(), cubic.residuals});
    return true;
  };
  const Branch branch = pseudo_arclength(cubic, Vector::Zero(1), 0.0, cubic_settings(2.9), record);
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  ASSERT_EQ(branch.points.back().p, 2.9);
  const std::vector<StepWork> steps = work_per_step(branch, totals);
  ASSERT_GE(steps.size(), 3u);
  const StepWork& first = steps.front();
  for (std::size_t i = 0; i < steps.size(); ++i) {
    SCOPED_TRACE("step " + std::to_string(i + 1) + " of " + std::to_string(steps.size()));
    EXPECT_EQ(steps[i].factorizations - steps[i].iterations,
              first.factorizations - first.iterations);
    EXPECT_EQ(steps[i].residuals - steps[i].iterations, first.residuals - first.iterations);
  }
}

// The step after a landing on an intermediate parameter value grows from the nominal step, not
// from the shortened one; every value is a point of the branch exactly.
TEST(ContLanding, LandsOnEveryParameterValue) {
  CountingCubic cubic;
  Settings s = cubic_settings(3.0);
  s.parameter_values = {0.05, 1.0 / 3.0, 1.0, 2.95};
  const Branch branch = pseudo_arclength(cubic, Vector::Zero(1), 0.0, s);
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  for (double v : s.parameter_values) {
    int hits = 0;
    for (const Point& pt : branch.points)
      if (pt.p == v) {
        ++hits;
        EXPECT_NEAR(pt.x(0), CountingCubic::branch(v), 1e-10);
      }
    EXPECT_EQ(hits, 1) << "p = " << v;
  }
  EXPECT_EQ(branch.points.back().p, 3.0);
  // 0.05 is reached from 0 by a step of about 0.05 (arclength ~ 0.05 sqrt(1 + 1)); the next
  // step is not limited by that shortened one.
  ASSERT_GE(branch.points.size(), 3u);
  EXPECT_EQ(branch.points[1].p, 0.05);
  EXPECT_GT(branch.points[2].step, 2.0 * branch.points[1].step);
}

// Through a fold: x^2 + p^2 = 1 from (1, 0) up to the limit point p = 1 and back down on the
// x < 0 side to p_min = -0.6. The value 0.5 is crossed twice (before and after the fold) and
// landed on both times; the last point is on p_min exactly.
TEST(ContLanding, BranchThroughAFoldLandsOnTheLowerBound) {
  test::CircleProblem circle;
  Settings s;
  s.step_initial = 0.05;
  s.step_max = 0.2;
  s.p_min = -0.6;
  s.p_max = 2.0;
  s.parameter_values = {0.5};
  const Branch branch = pseudo_arclength(circle, Vector::Constant(1, 1.0), 0.0, s);
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  EXPECT_EQ(branch.points.back().p, -0.6);
  EXPECT_NEAR(branch.points.back().x(0), -0.8, 1e-10);
  std::vector<double> x_at_half;
  for (const Point& pt : branch.points)
    if (pt.p == 0.5) x_at_half.push_back(pt.x(0));
  ASSERT_EQ(x_at_half.size(), 2u);
  EXPECT_NEAR(x_at_half[0], std::sqrt(0.75), 1e-10);
  EXPECT_NEAR(x_at_half[1], -std::sqrt(0.75), 1e-10);
  int limit_points = 0;
  for (const Event& e : branch.events) limit_points += e.type == EventType::kLimitPoint;
  EXPECT_EQ(limit_points, 1);
}

// A bound just below a fold (the tangent nearly normal to p there): still landed on exactly.
TEST(ContLanding, BoundJustBelowAFold) {
  test::CircleProblem circle;
  Settings s;
  s.step_initial = 0.05;
  s.step_max = 0.2;
  s.p_max = 0.9999;
  const Branch branch = pseudo_arclength(circle, Vector::Constant(1, 1.0), 0.0, s);
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  EXPECT_EQ(branch.points.back().p, 0.9999);
  EXPECT_NEAR(branch.points.back().x(0), std::sqrt(1.0 - 0.9999 * 0.9999), 1e-8);
}

// Natural continuation hits its targets as before (parameter values 1/n, ..., 1 of a load-
// factor driver): every value is a point, the run completes at the last one.
TEST(ContLanding, NaturalHitsNominalLoadFactors) {
  CountingCubic cubic;
  Settings s = cubic_settings(INFINITY);
  s.method = Method::kNatural;
  const int n = 7;
  for (int i = 1; i <= n; ++i) s.parameter_values.push_back(static_cast<double>(i) / n);
  const Branch branch = natural(cubic, Vector::Zero(1), 0.0, s);
  ASSERT_EQ(branch.status, Status::kCompleted) << branch.reason;
  ASSERT_EQ(branch.points.size(), static_cast<std::size_t>(n + 1));
  for (int i = 1; i <= n; ++i) EXPECT_EQ(branch.points[i].p, s.parameter_values[i - 1]);
}

// A bound a little beyond the step's reach is landed on by one step stretched to it, not by a
// step and a sliver after it; one further than the stretch allows is not. Steps held constant
// (no growth), so that the runs compared take the same steps up to the last.
class StretchedLanding : public ::testing::TestWithParam<Method> {
 protected:
  Branch run(double p_max, double stretch) {
    CountingCubic cubic;
    Settings s = cubic_settings(p_max);
    s.method = GetParam();
    s.step_initial = 0.3;
    s.step_max = 1.0;
    s.step_growth_max = 1.0;
    s.target_iterations = 100;
    s.landing_stretch = stretch;
    const Branch b = GetParam() == Method::kNatural
                         ? natural(cubic, Vector::Zero(1), 0.0, s)
                         : pseudo_arclength(cubic, Vector::Zero(1), 0.0, s);
    EXPECT_EQ(b.status, Status::kReachedBound) << b.reason;
    EXPECT_EQ(b.points.back().p, p_max);
    EXPECT_NEAR(b.points.back().x(0), CountingCubic::branch(p_max), 1e-10);
    return b;
  }
};

TEST_P(StretchedLanding, ATargetJustBeyondAStepTakesOneStepNotASliver) {
  // Where the unstretched run's last step is a sliver: the bound 10 % of a step past its
  // penultimate point.
  const Branch probe = run(2.0, 0.0);
  ASSERT_GE(probe.points.size(), 4u);
  const std::size_t k = probe.points.size() - 2;  // the point before the last step
  const double p_k = probe.points[k].p, p_before = probe.points[k - 1].p;
  const double near = p_k + 0.1 * (p_k - p_before);
  const double far = p_k + 0.5 * (p_k - p_before);
  const Branch sliver = run(near, 0.0);
  const Branch stretched_run = run(near, 0.3);
  EXPECT_EQ(stretched_run.points.size() + 1, sliver.points.size());
  const Point& last = stretched_run.points.back();
  EXPECT_GT(last.step, 1.05 * 0.3);
  EXPECT_LE(last.step, 1.3 * 0.3 * (1 + 1e-9) + (GetParam() == Method::kNatural ? 0 : 0.02));
  // Half a step past it: beyond the stretch, a step and then the rest.
  EXPECT_EQ(run(far, 0.3).points.size(), run(far, 0.0).points.size());
}

// A bound one step_max ahead in p (w |p - p0| = step_max: a path whose depth_max is its
// step_max) is reached in one pseudo-arclength step, although that step's arclength exceeds
// step_max by its x-part: the stretch bounds the p-part; without it, a step of step_max and a
// sliver to the bound. (w = 3: the tangent is mostly p, as on an indentation path.)
TEST(ContLanding, ABoundOneStepMaxAheadInPIsOneStep) {
  for (double stretch : {0.3, 0.0}) {
    CountingCubic cubic;
    Settings s = cubic_settings(0.5 / 3.0);
    s.parameter_weight = 3.0;
    s.step_initial = 0.5;
    s.step_max = 0.5;
    s.landing_stretch = stretch;
    const Branch b = pseudo_arclength(cubic, Vector::Zero(1), 0.0, s);
    ASSERT_EQ(b.status, Status::kReachedBound) << b.reason;
    EXPECT_EQ(b.points.back().p, 0.5 / 3.0);
    EXPECT_EQ(b.points.size(), stretch > 0 ? 2u : 3u) << "landing_stretch " << stretch;
  }
}

INSTANTIATE_TEST_SUITE_P(Steppers, StretchedLanding,
                         ::testing::Values(Method::kNatural, Method::kPseudoArclength));

}  // namespace
}  // namespace si::cont
