// The curve-feature detector (curve_features.hpp), tested first for what it must not report:
// an exactly linear segment between strongly curved neighbours (second differences at roundoff),
// a convex piecewise-smooth curve whose pieces alternate in curvature across kinks at signature
// changes (contact-like), convex curves with a vanishing or roundoff-level curvature; then for
// what it must: a smooth inflection and a minimum of the slope (minimum tangent stiffness), found
// and located next to kinks. Each "must not" case also checks that the raw indicator does change
// sign between accepted points, i.e. that the previous detector (any raw sign change) would have
// reported it.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "../verification_record.hpp"
#include "branch_test_support.hpp"
#include "continuation/curve_features.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

using Curve = std::function<double(double)>;
using Signature = std::function<int(double)>;

// sinh(x) = sinh(p): the branch is x = p (Newton needs iterations); monitors a = curve(x),
// b = x, f = a second curve; signature = signature(x).
class CurveProblem final : public test::DenseProblem {
 public:
  CurveProblem(
      Curve a, Signature signature, Curve f = [](double x) { return x; })
      : a_(std::move(a)), f_(std::move(f)), signature_(std::move(signature)) {}
  int size() const override { return 1; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F = Vector::Constant(1, std::sinh(x(0)) - std::sinh(p));
    return true;
  }
  Matrix jacobian(const Vector& x, double /*p*/) const override {
    return Matrix::Constant(1, 1, std::cosh(x(0)));
  }
  std::vector<std::string> monitor_names() const override { return {"a", "b", "f"}; }
  Vector monitors(const Vector& x, double /*p*/) override {
    return Vector{{a_(x(0)), x(0), f_(x(0))}};
  }
  std::vector<int> signature(const Vector& x, double /*p*/) override { return {signature_(x(0))}; }

 private:
  Curve a_;
  Curve f_;
  Signature signature_;
};

Settings feature_settings(double p_min, double p_max) {
  Settings s;
  s.step_initial = 0.02;
  s.step_max = 0.05;
  s.p_min = p_min;
  s.p_max = p_max;
  s.detect_limit_points = false;
  s.inflections = {{"a", "b"}};
  s.event_tolerance = 1e-9;
  return s;
}

Branch trace(CurveProblem& problem, const Settings& s, double p0) {
  const Branch branch = pseudo_arclength(problem, Vector::Constant(1, p0), p0, s);
  EXPECT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  return branch;
}

// Sign changes of the raw indicator g = a'' b' - a' b'' between accepted points: what the
// previous detector reported as inflections.
int raw_sign_changes(const Branch& branch) {
  int changes = 0;
  double previous = 0.0;
  for (const Point& pt : branch.points) {
    const double g = pt.monitor_curvatures(0) * pt.monitor_slopes(1) -
                     pt.monitor_slopes(0) * pt.monitor_curvatures(1);
    if (previous != 0.0 && g != 0.0 && (g > 0.0) != (previous > 0.0)) ++changes;
    if (g != 0.0) previous = g;
  }
  return changes;
}

int no_signature(double) {
  return 0;
}

// a = 3x + C (1.2 - x)_+^3 - C (x - 1.8)_+^3: convex, exactly linear on [1.2, 1.8], concave; the
// curvature is 6 C |distance| outside (up to ~1e7 here) and roundoff inside. No inflection point
// exists: the sign change is spread over a straight segment.
TEST(ContCurveFeatures, ExactlyLinearSegmentIsNoInflection) {
  const double C = 1e6;
  CurveProblem problem(
      [C](double x) {
        return 3.0 * x + C * std::pow(std::max(0.0, 1.2 - x), 3) -
               C * std::pow(std::max(0.0, x - 1.8), 3);
      },
      no_signature);
  const Branch branch = trace(problem, feature_settings(0.0, 3.0), 0.0);
  EXPECT_TRUE(test::events_of(branch, EventType::kInflection).empty());
  EXPECT_GE(raw_sign_changes(branch), 1);
  // Inside the segment every point is unsigned (within its noise estimate).
  CurveScales scales;
  for (const Point& pt : branch.points) scales.include(pt);
  const Indicator ind{EventType::kInflection, 0, 1};
  int inside = 0;
  for (const Point& pt : branch.points) {
    if (pt.p <= 1.2 + 1e-3 || pt.p >= 1.8 - 1e-3) continue;
    ++inside;
    EXPECT_EQ(resolved_sign(feature_value(ind, pt, scales), feature_settings(0, 1)), 0)
        << "x = " << pt.p;
  }
  EXPECT_GE(inside, 5);
}

// Kinks at x = 0.5, 1, ..., 2.5 where the signature (the piece index) changes, slopes jumping up
// by 1 (a convex curve overall, like force against curvature with nodes entering contact), pieces
// alternately concave and convex: the raw indicator changes sign at every kink; the detector
// reports the signature changes and no inflection.
TEST(ContCurveFeatures, KinksAtSignatureChangesAreNoInflections) {
  const auto piece = [](double x) { return static_cast<int>(std::floor(x / 0.5)); };
  CurveProblem problem(
      [piece](double x) {
        const int k = piece(x);
        double a = x;
        for (int j = 1; j <= 5; ++j) a += std::max(0.0, x - 0.5 * j);
        const double bump = (x - 0.5 * k) * (0.5 * (k + 1) - x);
        return a + (k % 2 == 0 ? 1.0 : -1.0) * bump;
      },
      piece);
  const Branch branch = trace(problem, feature_settings(0.1, 2.9), 0.1);
  EXPECT_TRUE(test::events_of(branch, EventType::kInflection).empty());
  EXPECT_EQ(test::events_of(branch, EventType::kSignatureChange).size(), 5u);
  EXPECT_GE(raw_sign_changes(branch), 4);
}

// Convex curves: x^4 + x (curvature vanishing at x = 0 without changing sign) and x + 1e-12 x^2
// (convex in exact arithmetic, roundoff in floating point): no inflection.
TEST(ContCurveFeatures, ConvexCurvesHaveNoInflection) {
  CurveProblem quartic([](double x) { return x * x * x * x + x; }, no_signature);
  const Branch a = trace(quartic, feature_settings(-1.0, 1.0), -1.0);
  EXPECT_TRUE(test::events_of(a, EventType::kInflection).empty());

  CurveProblem straight([](double x) { return x + 1e-12 * x * x; }, no_signature);
  const Branch b = trace(straight, feature_settings(-1.0, 3.0), -1.0);
  EXPECT_TRUE(test::events_of(b, EventType::kInflection).empty());
  EXPECT_GE(raw_sign_changes(b), 1);
}

// a = tanh(2(x - 1)) + 0.1 x + (x - 0.4)_+ + (x - 2.2)_+ against b = x: a smooth inflection at
// x = 1 between two kinks (signature changes at 0.4 and 2.2). f = (x - 1)^3 + 2 x against p: its
// slope 3 (x - 1)^2 + 2 has its minimum at x = 1 (the minimum tangent stiffness of a force).
TEST(ContCurveFeatures, SmoothInflectionAndSlopeMinimumFoundNextToKinks) {
  CurveProblem problem(
      [](double x) {
        return std::tanh(2.0 * (x - 1.0)) + 0.1 * x + std::max(0.0, x - 0.4) +
               std::max(0.0, x - 2.2);
      },
      [](double x) { return (x > 0.4 ? 1 : 0) + (x > 2.2 ? 1 : 0); },
      [](double x) { return std::pow(x - 1.0, 3) + 2.0 * x; });
  Settings s = feature_settings(0.0, 3.0);
  s.slope_extremum_monitors = {"a", "f"};
  const Branch branch = trace(problem, s, 0.0);
  const auto inflections = test::events_of(branch, EventType::kInflection);
  ASSERT_EQ(inflections.size(), 1u);
  EXPECT_TRUE(inflections[0].located);
  // The bracket is 1e-9; the root moves by the indicator's error over its slope (~1e-8 / O(1)).
  EXPECT_NEAR(inflections[0].p, 1.0, 1e-6);
  si::test::record_verification_absolute("continuation-library",
                                         "curve features: inflection of tanh next to kinks", 1.0,
                                         inflections[0].p, 1e-6, "exact: x = 1");
  const auto maxima = test::events_of(branch, EventType::kSlopeMax);
  const auto minima = test::events_of(branch, EventType::kSlopeMin);
  ASSERT_EQ(maxima.size(), 1u);  // of a: its slope 4 sech^2 + 0.1 (+ kinks) peaks at x = 1
  EXPECT_EQ(maxima[0].monitor, "a");
  EXPECT_NEAR(maxima[0].p, 1.0, 1e-6);
  ASSERT_EQ(minima.size(), 1u);
  EXPECT_EQ(minima[0].monitor, "f");
  EXPECT_NEAR(minima[0].p, 1.0, 1e-6);
  si::test::record_verification_absolute("continuation-library",
                                         "curve features: minimum slope of (x-1)^3 + 2x", 1.0,
                                         minima[0].p, 1e-6, "exact: x = 1");
  EXPECT_EQ(test::events_of(branch, EventType::kSignatureChange).size(), 2u);
}

}  // namespace
}  // namespace si::cont
