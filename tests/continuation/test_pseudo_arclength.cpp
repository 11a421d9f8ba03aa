// Pseudo-arclength continuation through limit points: the circle x^2 + p^2 = 1 all the way
// round, and the fold of the 1-D Bratu problem.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../verification_record.hpp"
#include "branch_test_support.hpp"
#include "bratu_problem.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "dense_test_problems.hpp"

namespace si::cont {
namespace {

Settings circle_settings(Predictor predictor, double natural_corrector_slope = 0.0) {
  Settings s;
  s.natural_corrector_slope = natural_corrector_slope;
  s.predictor = predictor;
  s.step_initial = 0.05;
  s.step_max = 0.2;
  s.event_tolerance = 1e-9;
  s.max_steps = 400;
  return s;
}

// Stops once the branch is back at p >= 0 on the x > 0 side after visiting x < 0.
Callback stop_when_closed() {
  return [visited_left = false](const Point& pt, const Branch&) mutable {
    if (pt.x(0) < 0.0) visited_left = true;
    return !(visited_left && pt.x(0) > 0.0 && pt.p >= 0.0);
  };
}

void expect_full_circle(Predictor predictor, double natural_corrector_slope = 0.0) {
  test::CircleProblem circle;
  const Settings settings = circle_settings(predictor, natural_corrector_slope);
  const Branch branch =
      pseudo_arclength(circle, Vector::Constant(1, 1.0), 0.0, settings, stop_when_closed());
  ASSERT_EQ(branch.status, Status::kStoppedByCallback) << branch.reason;
  for (const auto& pt : branch.points)
    EXPECT_NEAR(pt.x(0) * pt.x(0) + pt.p * pt.p, 1.0, 1e-9);  // corrector tolerance 1e-10 (scale 1)

  // Both limit points, p = +1 first (direction +1), then p = -1. The bracket is located to
  // event_tolerance in arclength; |p| - 1 is second order in it, x first order.
  const auto limits = test::events_of(branch, EventType::kLimitPoint);
  ASSERT_EQ(limits.size(), 2u);
  EXPECT_TRUE(limits[0].located && limits[1].located);
  EXPECT_NEAR(limits[0].p, 1.0, settings.event_tolerance);
  EXPECT_NEAR(limits[1].p, -1.0, settings.event_tolerance);
  const std::string label =
      std::string(predictor == Predictor::kTangent ? "tangent" : "secant") +
      (natural_corrector_slope > 0.0 ? ", natural corrector on steep steps" : "");
  si::test::record_verification_absolute("continuation-library",
                                         "circle, " + label + " predictor: limit point p = +1", 1.0,
                                         limits[0].p, settings.event_tolerance, "exact");
  si::test::record_verification_absolute("continuation-library",
                                         "circle, " + label + " predictor: limit point p = -1",
                                         -1.0, limits[1].p, settings.event_tolerance, "exact");
  EXPECT_NEAR(limits[0].x(0), 0.0, 2.0 * settings.event_tolerance);
  EXPECT_NEAR(limits[1].x(0), 0.0, 2.0 * settings.event_tolerance);
  EXPECT_LE(limits[0].accuracy, settings.event_tolerance);

  // All the way round: the polar angle advances at every step and sums to one full turn plus
  // the overshoot past the start (the callback stops at the first point past it).
  double turned = 0.0;
  for (std::size_t i = 1; i < branch.points.size(); ++i) {
    const Point& a = branch.points[i - 1];
    const Point& b = branch.points[i];
    const double dtheta =
        std::remainder(std::atan2(b.p, b.x(0)) - std::atan2(a.p, a.x(0)), 2 * M_PI);
    EXPECT_GT(dtheta, 0.0) << "step " << i << " went backwards";
    turned += dtheta;
  }
  const Point& last = branch.points.back();
  const double overshoot = std::atan2(last.p, last.x(0));  // angle past the start, >= 0
  EXPECT_GE(overshoot, 0.0);
  EXPECT_LE(overshoot, settings.step_max);
  EXPECT_NEAR(turned, 2.0 * M_PI + overshoot, 1e-12);
}

TEST(ContPseudoArclength, CircleTracedAllRoundTangentPredictor) {
  expect_full_circle(Predictor::kTangent);
}

TEST(ContPseudoArclength, CircleTracedAllRoundSecantPredictor) {
  expect_full_circle(Predictor::kSecant);
}

// Steep steps corrected at fixed p (Settings::natural_corrector_slope): the circle is still
// traced all round through both folds, where |dp/ds| -> 0 and Keller's step takes over.
TEST(ContPseudoArclength, CircleTracedAllRoundWithNaturalCorrectorOnSteepSteps) {
  expect_full_circle(Predictor::kTangent, 0.5);
}

TEST(ContPseudoArclength, DirectionMinusOneGoesDownFirst) {
  test::CircleProblem circle;
  Settings settings = circle_settings(Predictor::kTangent);
  settings.direction = -1;
  settings.max_steps = 3;
  const Branch branch = pseudo_arclength(circle, Vector::Constant(1, 1.0), 0.0, settings);
  EXPECT_EQ(branch.status, Status::kMaxSteps);
  ASSERT_EQ(branch.points.size(), 4u);
  EXPECT_LT(branch.points.back().p, 0.0);
}

// The parameter bound is located exactly: the last point lies on p = p_max.
TEST(ContPseudoArclength, StopsExactlyAtParameterBound) {
  test::CircleProblem circle;
  Settings settings = circle_settings(Predictor::kTangent);
  settings.p_max = 0.6;
  const Branch branch = pseudo_arclength(circle, Vector::Constant(1, 1.0), 0.0, settings);
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  EXPECT_EQ(branch.points.back().p, 0.6);
  EXPECT_NEAR(branch.points.back().x(0), 0.8, 1e-10);
}

// The fold of the discrete Bratu problem on n interior nodes; `solves` counts the linear solves.
Event bratu_fold(int n, double natural_corrector_slope = 0.0, int* solves = nullptr) {
  test::BratuProblem bratu(n);
  Settings settings;
  settings.natural_corrector_slope = natural_corrector_slope;
  settings.step_initial = 0.1;
  settings.step_max = 0.5;
  settings.p_min = 0.5;  // stop on the upper branch on the way back
  settings.max_steps = 200;
  settings.newton.residual_scale = 10.0;  // |lambda e^u| near the fold
  settings.detect_bifurcations = true;    // a fold is not a bifurcation: none expected
  const Branch branch = pseudo_arclength(bratu, Vector::Zero(n), 1.0, settings);  // lower branch
  EXPECT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  EXPECT_TRUE(test::events_of(branch, EventType::kBifurcation).empty());
  const auto folds = test::events_of(branch, EventType::kLimitPoint);
  EXPECT_EQ(folds.size(), 1u);
  EXPECT_TRUE(!folds.empty() && folds[0].located);
  for (const Point& pt : branch.points) {  // every point on the branch, whichever corrector
    Vector F;
    bratu.residual(pt.x, pt.p, F);
    EXPECT_LE(F.lpNorm<Eigen::Infinity>(), 1e-10 * 10.0) << "p = " << pt.p;
  }
  if (solves) *solves = bratu.solves();
  return folds.empty() ? Event{} : folds[0];
}

// The same fold with the steep steps corrected at fixed p: located at the same lambda (both to
// the event tolerance, 1e-8 in arclength, second order in lambda at a fold), with fewer linear
// solves (one per Newton iteration on the steep steps instead of the bordered two).
TEST(ContPseudoArclength, NaturalCorrectorOnSteepStepsFindsTheSameFoldWithFewerSolves) {
  int keller = 0, local = 0;
  const double l_keller = bratu_fold(200, 0.0, &keller).p;
  const double l_local = bratu_fold(200, 0.5, &local).p;
  EXPECT_NEAR(l_local, l_keller, 1e-10);
  EXPECT_LT(local, 0.85 * keller) << local << " solves against " << keller;
  std::printf("Bratu fold n = 200: %d solves (Keller), %d (natural corrector on steep steps)\n",
              keller, local);
}

// Bratu fold: lambda_c = 3.513830719 (Boyd 1986; Mohsen 2014), acceptance 1e-4. The scheme is
// O(h^2): measured errors -4.5e-5 (n = 200) and -1.1e-5 (n = 400); Richardson extrapolation of
// the two (h = 1/(n+1)) removes the h^2 term: measured error 9e-11 (docs/theory/continuation.md).
TEST(ContPseudoArclength, BratuFoldBoyd1986) {
  const double lambda_c = test::bratu_critical_lambda();
  EXPECT_NEAR(lambda_c, 3.513830719, 1e-9);  // the closed form against the published digits

  const int coarse = 200;
  const int fine = 400;
  const double l_coarse = bratu_fold(coarse).p;
  const double l_fine = bratu_fold(fine).p;
  const double h2_coarse = 1.0 / ((coarse + 1.0) * (coarse + 1.0));
  const double h2_fine = 1.0 / ((fine + 1.0) * (fine + 1.0));
  const double richardson = (l_fine * h2_coarse - l_coarse * h2_fine) / (h2_coarse - h2_fine);
  EXPECT_NEAR(l_fine, lambda_c, 1e-4);      // acceptance, single grid
  EXPECT_NEAR(richardson, lambda_c, 1e-5);  // discretisation error below 1e-5 asked for
  const char* const boyd = "Boyd 1986: lambda_c = 3.513830719";
  si::test::record_verification_absolute("continuation-library", "1-D Bratu fold lambda_c, n = 400",
                                         lambda_c, l_fine, 1e-4, boyd);
  si::test::record_verification_absolute("continuation-library",
                                         "1-D Bratu fold lambda_c, Richardson n = 200, 400",
                                         lambda_c, richardson, 1e-5, boyd);
  std::printf(
      "Bratu fold: n=%d %.10f (err %.2e), n=%d %.10f (err %.2e), Richardson %.10f (err %.2e)\n",
      coarse, l_coarse, l_coarse - lambda_c, fine, l_fine, l_fine - lambda_c, richardson,
      richardson - lambda_c);
}

// Pitchfork x (p - x^2) = 0 along the trivial branch x = 0: det J = p changes sign at p = 0
// while dp/ds does not, so the augmented determinant flags a bifurcation there.
class PitchforkProblem final : public test::DenseProblem {
 public:
  int size() const override { return 1; }
  bool residual(const Vector& x, double p, Vector& F) override {
    F = Vector::Constant(1, x(0) * (p - x(0) * x(0)));
    return true;
  }
  test::Matrix jacobian(const Vector& x, double p) const override {
    return test::Matrix::Constant(1, 1, p - 3.0 * x(0) * x(0));
  }
};

TEST(ContPseudoArclength, PitchforkBifurcationDetected) {
  PitchforkProblem problem;
  Settings settings;
  settings.detect_bifurcations = true;
  settings.step_initial = 0.3;
  settings.step_max = 0.3;
  settings.p_max = 1.0;
  settings.event_tolerance = 1e-10;
  const Branch branch = pseudo_arclength(problem, Vector::Zero(1), -1.0, settings);
  EXPECT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  const auto bif = test::events_of(branch, EventType::kBifurcation);
  ASSERT_EQ(bif.size(), 1u);
  EXPECT_TRUE(bif[0].located);
  EXPECT_NEAR(bif[0].p, 0.0, settings.event_tolerance);
  EXPECT_TRUE(test::events_of(branch, EventType::kLimitPoint).empty());
}

}  // namespace
}  // namespace si::cont
