// Event location on branches with known answers: y = p^3 - 3p (extrema at p = -1 (max) and
// p = +1 (min), zeros at p = 0, +-sqrt(3), inflection of y against p at p = 0), by both methods.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "../verification_record.hpp"
#include "branch_test_support.hpp"
#include "continuation/natural.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

// Monitors of the cubic branch plus q = p^3 + p, a nonlinear monotone abscissa: d2y/dq2 =
// 24 p / (3p^2 + 1)^3, so y(q) also has its inflection at p = 0. The signature is that of y + 1,
// which changes where p^3 - 3p = -1, i.e. p = 2 cos(theta), cos(3 theta) = -1/2: p = 2 cos(8 pi/9),
// 2 cos(4 pi/9), 2 cos(2 pi/9); not at y's own zero p = 0, where the inflection is (the
// curve-feature detector never reports a feature across a signature change: a kink there).
class CubicWithAbscissa final : public Problem {
 public:
  int size() const override { return cubic_.size(); }
  bool residual(const Vector& x, double p, Vector& F) override { return cubic_.residual(x, p, F); }
  bool factorize(const Vector& x, double p) override {
    ++factorizations;
    return cubic_.factorize(x, p);
  }
  bool solve(Vector& b) override { return cubic_.solve(b); }
  std::vector<std::string> monitor_names() const override { return {"y", "p", "q"}; }
  Vector monitors(const Vector& x, double p) override {
    ++monitor_evaluations;
    return Vector{{x(0), p, p * p * p + p}};
  }
  Vector monitor_subset(const Vector& x, double p, const std::vector<int>& which) override {
    asked_for_subsets.insert(which.begin(), which.end());
    return Problem::monitor_subset(x, p, which);
  }
  std::vector<int> signature(const Vector& x, double /*p*/) override { return {x(0) > -1.0}; }

  int factorizations = 0;
  int monitor_evaluations = 0;      // the points analysed, trial points of a location included
  std::set<int> asked_for_subsets;  // the monitors the derivatives along the branch evaluated

 private:
  test::CubicBranchProblem cubic_;
};

Settings event_settings(Method method) {
  Settings s;
  s.method = method;
  s.step_initial = 0.05;
  s.step_max = 0.25;
  s.p_min = -2.5;
  s.p_max = 2.5;
  s.event_tolerance = 1e-9;
  s.extremum_monitors = {"y"};
  s.zero_crossing_monitors = {"y"};
  s.inflections = {{"y", "p"}, {"y", "q"}};
  return s;
}

Branch run(Method method) {
  CubicWithAbscissa problem;
  const Settings s = event_settings(method);
  const Vector x0 = Vector::Constant(1, test::CubicBranchProblem::branch(-2.4));
  return method == Method::kNatural ? natural(problem, x0, -2.4, s)
                                    : pseudo_arclength(problem, x0, -2.4, s);
}

// Location accuracy: the bracket is event_tolerance (1e-9) wide; the indicators themselves carry
// finite-difference errors (point_analysis.hpp): ~1e-10 relative for slopes, ~1e-8 for second
// derivatives, which move the root by that over the indicator's slope (O(1) here).
constexpr double kSlopeRootTol = 1e-8;
constexpr double kCurvatureRootTol = 1e-6;

void expect_cubic_events(const Branch& branch) {
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  EXPECT_TRUE(test::events_of(branch, EventType::kLimitPoint).empty());

  const auto maxima = test::events_of(branch, EventType::kMonitorMax);
  const auto minima = test::events_of(branch, EventType::kMonitorMin);
  ASSERT_EQ(maxima.size(), 1u);
  ASSERT_EQ(minima.size(), 1u);
  EXPECT_EQ(maxima[0].monitor, "y");
  EXPECT_NEAR(maxima[0].p, -1.0, kSlopeRootTol);
  si::test::record_verification_absolute("continuation-library", "y = p^3 - 3p: maximum at p = -1",
                                         -1.0, maxima[0].p, kSlopeRootTol, "exact");
  // y(-1) = 2: y is flat there, so only the corrector's error (||F|| <= 1e-10, |dF/dx| >= 1)
  // remains.
  EXPECT_NEAR(maxima[0].monitors(0), 2.0, 1e-10);
  EXPECT_NEAR(minima[0].p, 1.0, kSlopeRootTol);
  si::test::record_verification_absolute("continuation-library", "y = p^3 - 3p: minimum at p = +1",
                                         1.0, minima[0].p, kSlopeRootTol, "exact");
  EXPECT_NEAR(minima[0].monitors(0), -2.0, 1e-10);

  const auto zeros = test::events_of(branch, EventType::kZeroCrossing);
  ASSERT_EQ(zeros.size(), 3u);
  const double expected_zeros[] = {-std::sqrt(3.0), 0.0, std::sqrt(3.0)};
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(zeros[i].located);
    // |dy/dp| = 6 at +-sqrt(3), 3 at 0: the bracket in p is at most event_tolerance.
    EXPECT_NEAR(zeros[i].p, expected_zeros[i], 1e-9);
    si::test::record_verification_absolute(
        "continuation-library", "y = p^3 - 3p: zero crossing " + std::to_string(i + 1) + " of 3",
        expected_zeros[i], zeros[i].p, 1e-9, "exact: 0, +-sqrt(3)");
  }

  const auto inflections = test::events_of(branch, EventType::kInflection);
  ASSERT_EQ(inflections.size(), 2u);
  for (const auto& e : inflections) {
    EXPECT_EQ(e.monitor, "y");
    EXPECT_TRUE(e.located);
    EXPECT_NEAR(e.p, 0.0, kCurvatureRootTol) << "against " << e.against;
    si::test::record_verification_absolute("continuation-library",
                                           "y = p^3 - 3p: inflection against " + e.against, 0.0,
                                           e.p, kCurvatureRootTol, "exact");
  }

  // The signature (sign of y + 1) changes at three points, located by bisection.
  const auto changes = test::events_of(branch, EventType::kSignatureChange);
  ASSERT_EQ(changes.size(), 3u);
  const double pi = std::acos(-1.0);
  const double expected_changes[] = {2.0 * std::cos(8.0 * pi / 9.0), 2.0 * std::cos(4.0 * pi / 9.0),
                                     2.0 * std::cos(2.0 * pi / 9.0)};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(changes[i].p, expected_changes[i], 1e-8);

  // Events are ordered along the branch and tagged with the step that contains them.
  for (std::size_t i = 1; i < branch.events.size(); ++i)
    EXPECT_LE(branch.events[i - 1].arclength, branch.events[i].arclength);
  for (const auto& e : branch.events) {
    ASSERT_GE(e.step, 1);
    ASSERT_LT(e.step, static_cast<int>(branch.points.size()));
    EXPECT_LE(branch.points[e.step - 1].p, e.p + 1e-12);
    EXPECT_GE(branch.points[e.step].p, e.p - 1e-12);
  }
}

TEST(ContEvents, CubicBranchNatural) {
  expect_cubic_events(run(Method::kNatural));
}

TEST(ContEvents, CubicBranchPseudoArclength) {
  expect_cubic_events(run(Method::kPseudoArclength));
}

TEST(ContEvents, UnknownMonitorRejected) {
  CubicWithAbscissa problem;
  Settings s = event_settings(Method::kNatural);
  s.extremum_monitors = {"force"};
  try {
    natural(problem, Vector::Constant(1, 0.0), 0.0, s);
    ADD_FAILURE() << "unknown monitor accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "continuation.extremum_monitors: unknown monitor 'force' (known: y, p, q)");
  }
}

TEST(ContEvents, SignatureChangeUnlocatedWhenNotAsked) {
  CubicWithAbscissa problem;
  Settings s = event_settings(Method::kNatural);
  s.locate_signature_changes = false;
  s.extremum_monitors.clear();
  s.zero_crossing_monitors.clear();
  s.inflections.clear();
  const Branch branch = natural(problem, Vector::Constant(1, 0.0), 0.0 - 0.3, s);
  const auto changes = test::events_of(branch, EventType::kSignatureChange);
  ASSERT_EQ(changes.size(), 2u);  // at 2 cos(4 pi/9) and 2 cos(2 pi/9)
  EXPECT_FALSE(changes[0].located);
  EXPECT_EQ(changes[0].p, branch.points[changes[0].step].p);  // reported at the later point
}

// With a value tolerance the location stops once |y - 1| is within it: the crossings are where
// y = 1 to that tolerance (p to it over |y'|, and the reported accuracy bounds the true
// distance), found at fewer trial points (each a corrector solve) than the 1e-9 bracket; without
// it (0) the location is the bracket's, as above. What must not change: the number of crossings.
TEST(ContEvents, LevelCrossingValueToleranceStopsWithinTheValue) {
  const double pi = std::acos(-1.0);
  const double expected[] = {2 * std::cos(7 * pi / 9), 2 * std::cos(5 * pi / 9),
                             2 * std::cos(pi / 9)};
  for (Method method : {Method::kNatural, Method::kPseudoArclength}) {
    int trial_points[2] = {0, 0};
    for (int loose = 0; loose < 2; ++loose) {
      Settings s = event_settings(method);
      s.zero_crossing_monitors.clear();
      s.extremum_monitors.clear();
      s.inflections.clear();
      const double tolerance = loose ? 1e-6 : 0.0;
      s.level_crossings = {{"y", 1.0, tolerance}};
      CubicWithAbscissa problem;
      const Vector x0 = Vector::Constant(1, test::CubicBranchProblem::branch(-2.4));
      const Branch b = method == Method::kNatural ? natural(problem, x0, -2.4, s)
                                                  : pseudo_arclength(problem, x0, -2.4, s);
      trial_points[loose] = problem.monitor_evaluations;
      const auto crossings = test::events_of(b, EventType::kZeroCrossing);
      ASSERT_EQ(crossings.size(), 3u);
      for (int i = 0; i < 3; ++i) {
        const Event& e = crossings[i];
        EXPECT_TRUE(e.located);
        const double slope = 3 * expected[i] * expected[i] - 3;  // dy/dp at the crossing
        if (loose) {
          EXPECT_LE(std::abs(e.monitors(0) - 1.0), tolerance);
          EXPECT_NEAR(e.p, expected[i], 1.01 * tolerance / std::abs(slope));
        } else {
          EXPECT_NEAR(e.p, expected[i], 1e-9);
        }
      }
    }
    EXPECT_LT(trial_points[1], trial_points[0]) << "the value test saves no solve";
  }
}

}  // namespace
}  // namespace si::cont

namespace si::cont {
namespace {

// A level crossing is the zero crossing of m - level: y = p^3 - 3p = 1 at p = 2 cos(theta),
// cos(3 theta) = 1/2, i.e. theta = pi/9, 5 pi/9, 7 pi/9 (ascending p: 7, 5, 1). It must not
// report y's zeros.
TEST(ContEvents, LevelCrossingLocatedAtTheLevel) {
  for (Method method : {Method::kNatural, Method::kPseudoArclength}) {
    Settings s = event_settings(method);
    s.zero_crossing_monitors.clear();
    s.extremum_monitors.clear();
    s.inflections.clear();
    s.level_crossings = {{"y", 1.0}};
    CubicWithAbscissa problem;
    const Vector x0 = Vector::Constant(1, test::CubicBranchProblem::branch(-2.4));
    const Branch b = method == Method::kNatural ? natural(problem, x0, -2.4, s)
                                                : pseudo_arclength(problem, x0, -2.4, s);
    const auto crossings = test::events_of(b, EventType::kZeroCrossing);
    ASSERT_EQ(crossings.size(), 3u);
    const double pi = std::acos(-1.0);
    const double expected[] = {2 * std::cos(7 * pi / 9), 2 * std::cos(5 * pi / 9),
                               2 * std::cos(pi / 9)};
    for (int i = 0; i < 3; ++i) {
      EXPECT_TRUE(crossings[i].located);
      EXPECT_NEAR(crossings[i].p, expected[i], 1e-9);
      EXPECT_EQ(crossings[i].monitor, "y");
    }
  }
}

// The derivatives along the branch are taken only for the monitors that need them: those of
// the extremum indicator (y) and the caller's slope_monitors (q), never p's, whose slope stays NaN.
// Off-branch evaluations of a costly monitor are what this saves (issue 16: the damage probe).
// The slopes that are computed are right: dm/ds = dm/dp dp/ds with y = p^3 - 3p, q = p^3 + p.
TEST(ContEvents, SlopesOnlyOfTheMonitorsThatNeedThem) {
  for (Method method : {Method::kNatural, Method::kPseudoArclength}) {
    Settings s = event_settings(method);
    s.zero_crossing_monitors.clear();
    s.inflections.clear();
    s.slope_monitors = {"q"};
    CubicWithAbscissa problem;
    const Vector x0 = Vector::Constant(1, test::CubicBranchProblem::branch(-2.4));
    const Branch b = method == Method::kNatural ? natural(problem, x0, -2.4, s)
                                                : pseudo_arclength(problem, x0, -2.4, s);
    EXPECT_EQ(problem.asked_for_subsets, (std::set<int>{0, 2}));
    ASSERT_GT(b.points.size(), 10u);
    for (const Point& pt : b.points) {
      ASSERT_EQ(pt.monitor_slopes.size(), 3);
      EXPECT_TRUE(std::isnan(pt.monitor_slopes(1)));
      const double p = pt.p;
      EXPECT_NEAR(pt.monitor_slopes(0), (3 * p * p - 3) * pt.tangent_p, 1e-6);
      EXPECT_NEAR(pt.monitor_slopes(2), (3 * p * p + 1) * pt.tangent_p, 1e-6);
    }
  }
  Settings s = event_settings(Method::kNatural);
  s.slope_monitors = {"z"};
  CubicWithAbscissa problem;
  try {
    natural(problem, Vector::Constant(1, test::CubicBranchProblem::branch(-2.4)), -2.4, s);
    ADD_FAILURE() << "an unknown slope monitor was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("slope_monitors: unknown monitor 'z'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace si::cont
