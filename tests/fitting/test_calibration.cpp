// The calibration driver (fitting/calibration.hpp) on cheap models standing in for expensive
// ones: recovery of known parameters from noisy data, its statistics against the nonlinear
// fitter's (NIST-verified, analytic Jacobian), coverage of the joint confidence region, the
// identifiability warnings (and their absence), failures, interruption and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "fitting/builtin_models.hpp"
#include "fitting/calibration.hpp"
#include "fitting/curve_model.hpp"
#include "fitting/nlopt_status.hpp"
#include "synthetic_data.hpp"

namespace si::fit {
namespace {

using testing::grid;
using testing::sample;

// y = a x^b on x in [0.1, 2], the shape of a force-depth curve; a = 350, b = 1.37.
constexpr double kA = 350.0, kB = 1.37;
double truth(double x) {
  return kA * std::pow(x, kB);
}

CalibrationModel power_model(const Eigen::VectorXd& x) {
  return [x](const Eigen::VectorXd& c) {
    ModelOutput o;
    o.predicted = (c[0] * x.array().pow(c[1])).matrix();
    o.ok = true;
    return o;
  };
}

CalibrationProblem power_problem(const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
  CalibrationProblem p;
  p.x = x;
  p.y = y;
  p.parameters = {{"a", 100.0, 1000.0, 200.0}, {"b", 0.5, 3.0, 1.0}};
  p.model = power_model(x);
  return p;
}

// Homoscedastic noise of 1 % of the largest value, seeded.
Eigen::VectorXd noisy(const Eigen::VectorXd& x, unsigned seed) {
  return sample(x, truth, 0.01 * truth(x.maxCoeff()), seed);
}

TEST(Calibration, RecoversKnownParametersWithinTheConfidenceRegion) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 20);
  const Eigen::VectorXd y = noisy(x, 7);
  const CalibrationResult r = calibrate(power_problem(x, y), {});
  ASSERT_EQ(r.status, CalibrationStatus::kConverged) << r.reason;
  EXPECT_EQ(r.algorithm, "LN_BOBYQA");
  EXPECT_GT(r.nlopt_code, 0) << nlopt_code_name(r.nlopt_code);
  ASSERT_TRUE(r.statistics_available);
  const Eigen::Vector2d true_c(kA, kB);
  EXPECT_LE(r.ellipsoid.distance(r.parameters, true_c), 1.0);
  for (int j = 0; j < 2; ++j) {
    EXPECT_LE(r.ci_lower[j], true_c[j]) << r.names[j];
    EXPECT_GE(r.ci_upper[j], true_c[j]) << r.names[j];
  }
  EXPECT_TRUE(r.identifiability.identifiable()) << describe(r.identifiability.warnings[0], r.names);
  EXPECT_EQ(r.evaluations.jacobian, 4);  // central differences, 2 parameters
  EXPECT_EQ(r.evaluations.failed, 0);
  EXPECT_LT(r.evaluations.search, 100);

  // The same data through the nonlinear fitter (SLSQP + Levenberg-Marquardt, analytic Jacobian,
  // NIST-verified): the optimum to 1e-5 and the standard errors to 1e-3 - the difference is
  // BOBYQA's stopping tolerance and the finite-difference Jacobian.
  FitSettings fs;
  fs.start = Eigen::Vector2d(200.0, 1.0);
  const FitResult f = fit_curve(power_law(), x, y, fs);
  ASSERT_EQ(f.status, FitStatus::kConverged);
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(r.parameters[j], f.parameters[j], 1e-5 * f.parameters[j]) << r.names[j];
    EXPECT_NEAR(r.std_errors[j], f.std_errors[j], 1e-3 * f.std_errors[j]) << r.names[j];
  }
  EXPECT_NEAR(r.correlation(0, 1), f.covariance(0, 1) / (f.std_errors[0] * f.std_errors[1]), 1e-4);
}

// The joint 95 % region covers the truth in about 95 % of noisy repetitions (exact for a linear
// model; a power law over this range is close to linear in (a, b) at 1 % noise). 200 seeded
// trials: the count of a fair 95 % region is 190 +- 3 (binomial sd); required >= 180.
TEST(Calibration, JointRegionCoverage) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 15);
  int inside = 0, marginal_a = 0;
  for (unsigned seed = 1; seed <= 200; ++seed) {
    const CalibrationResult r = calibrate(power_problem(x, noisy(x, seed)), {});
    ASSERT_EQ(r.status, CalibrationStatus::kConverged) << seed << ": " << r.reason;
    inside += r.ellipsoid.distance(r.parameters, Eigen::Vector2d(kA, kB)) <= 1.0 ? 1 : 0;
    marginal_a += (r.ci_lower[0] <= kA && kA <= r.ci_upper[0]) ? 1 : 0;
  }
  std::printf(
      "[calibration] joint region covers the truth in %d of 200 trials, a's interval in %d\n",
      inside, marginal_a);
  EXPECT_GE(inside, 180);
  EXPECT_LE(inside, 199);  // a region that always covers is too wide
  EXPECT_GE(marginal_a, 180);
}

// y = a b x: only the product is determined. Every warning names both parameters. The two
// columns of J are exactly proportional here, so the covariance does not exist (rank-deficient:
// NaN, no correlation to test); the condition number and the null direction still say why.
TEST(Calibration, ParametersEnteringAsAProductAreFlagged) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 12);
  CalibrationProblem p;
  p.x = x;
  p.y = sample(
      x, [](double v) { return 6.0 * v; }, 0.05, 3);
  p.parameters = {{"a", 0.5, 5.0, 1.0}, {"b", 0.5, 5.0, 1.0}};
  p.model = [x](const Eigen::VectorXd& c) { return ModelOutput{c[0] * c[1] * x, true, "", ""}; };
  const CalibrationResult r = calibrate(p, {});
  ASSERT_TRUE(r.statistics_available) << r.reason;
  EXPECT_GT(r.nlopt_code, 0);
  EXPECT_NEAR(r.parameters[0] * r.parameters[1], 6.0, 0.05);
  bool correlated = false, conditioned = false, null_direction = false;
  for (const auto& w : r.identifiability.warnings) {
    EXPECT_EQ(w.parameters, (std::vector<int>{0, 1})) << describe(w, r.names);
    correlated = correlated || w.issue == IdentifiabilityIssue::kCorrelated;
    conditioned = conditioned || w.issue == IdentifiabilityIssue::kIllConditioned;
    null_direction = null_direction || w.issue == IdentifiabilityIssue::kNullDirection;
  }
  EXPECT_TRUE(conditioned && null_direction);
  EXPECT_TRUE(correlated || !r.covariance.allFinite());
  EXPECT_GT(r.identifiability.condition_number, 1e6);
}

// y = a b x + 0.01 a x^2: nearly proportional columns, a finite covariance, |r| > 0.99.
TEST(Calibration, NearlyProportionalParametersAreCorrelated) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 12);
  CalibrationProblem p;
  p.x = x;
  p.y = sample(
      x, [](double v) { return 6.0 * v + 0.02 * v * v; }, 0.05, 3);
  p.parameters = {{"a", 0.5, 5.0, 1.0}, {"b", 0.5, 5.0, 1.0}};
  p.model = [x](const Eigen::VectorXd& c) {
    return ModelOutput{(c[0] * c[1] * x.array() + 0.01 * c[0] * x.array().square()).matrix(), true,
                       "", ""};
  };
  const CalibrationResult r = calibrate(p, {});
  ASSERT_TRUE(r.statistics_available) << r.reason;
  ASSERT_TRUE(r.covariance.allFinite());
  std::printf("[calibration] a b x + 0.01 a x^2: correlation %.6f, condition number %.3g\n",
              r.correlation(0, 1), r.identifiability.condition_number);
  bool correlated = false;
  for (const auto& w : r.identifiability.warnings)
    if (w.issue == IdentifiabilityIssue::kCorrelated) {
      correlated = true;
      EXPECT_EQ(w.parameters, (std::vector<int>{0, 1}));
      EXPECT_NE(describe(w, r.names).find("a and b are correlated"), std::string::npos)
          << describe(w, r.names);
    }
  EXPECT_TRUE(correlated);
}

// A parameter the model ignores is reported as insensitive, and only that one.
TEST(Calibration, ParameterWithoutEffectIsInsensitive) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 12);
  CalibrationProblem p = power_problem(x, noisy(x, 5));
  p.parameters.push_back({"unused", 0.0, 1.0, 0.5});
  const auto inner = power_model(x);
  p.model = [inner](const Eigen::VectorXd& c) { return inner(c.head(2)); };
  const CalibrationResult r = calibrate(p, {});
  ASSERT_TRUE(r.statistics_available) << r.reason;
  ASSERT_EQ(r.identifiability.warnings.size(), 1u)
      << describe(r.identifiability.warnings[0], r.names);
  EXPECT_EQ(r.identifiability.warnings[0].issue, IdentifiabilityIssue::kInsensitive);
  EXPECT_EQ(r.identifiability.warnings[0].parameters, std::vector<int>{2});
}

TEST(Calibration, GradientAlgorithmWithFiniteDifferencesAgrees) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 20);
  const Eigen::VectorXd y = noisy(x, 7);
  CalibrationSettings s;
  s.algorithm = CalibrationAlgorithm::kGradient;
  s.max_evaluations = 300;
  const CalibrationResult g = calibrate(power_problem(x, y), s);
  const CalibrationResult d = calibrate(power_problem(x, y), {});
  ASSERT_EQ(g.status, CalibrationStatus::kConverged) << g.reason;
  EXPECT_EQ(g.algorithm, "LD_SLSQP");
  EXPECT_GT(g.nlopt_code, 0);
  for (int j = 0; j < 2; ++j)
    EXPECT_NEAR(g.parameters[j], d.parameters[j], 1e-4 * d.std_errors[j] + 1e-4 * d.parameters[j]);
}

// One parameter (NLopt's BOBYQA accepts n = 1, unlike Powell's original).
TEST(Calibration, OneParameter) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 10);
  CalibrationProblem p;
  p.x = x;
  p.y = sample(x, truth, 0.0, 0);
  p.parameters = {{"a", 10.0, 1000.0, 100.0}};
  p.model = [x](const Eigen::VectorXd& c) {
    return ModelOutput{(c[0] * x.array().pow(kB)).matrix(), true, "", ""};
  };
  const CalibrationResult r = calibrate(p, {});
  ASSERT_EQ(r.status, CalibrationStatus::kConverged) << r.reason;
  EXPECT_EQ(r.algorithm, "LN_BOBYQA");
  EXPECT_NEAR(r.parameters[0], kA, 1e-3);
}

// A model that fails in part of the box (a run that does not reach the last travel): the failures
// are counted, the search turns away and still finds the optimum. BOBYQA's first interpolation
// points lie at the start +- a tenth of each range, so b = 2 + 0.25 is tried and fails.
TEST(Calibration, FailedEvaluationsAreCountedAndAvoided) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 20);
  CalibrationProblem p = power_problem(x, sample(x, truth, 0.0, 0));
  p.parameters[1].start = 2.0;
  const auto inner = power_model(x);
  p.model = [inner](const Eigen::VectorXd& c) {
    if (c[1] > 2.1) return ModelOutput{{}, false, "diverged", ""};
    return inner(c);
  };
  const CalibrationResult r = calibrate(p, {});
  ASSERT_EQ(r.status, CalibrationStatus::kConverged) << r.reason;
  EXPECT_NEAR(r.parameters[1], kB, 1e-4);
  EXPECT_GE(r.evaluations.failed, 1);
}

TEST(Calibration, ModelFailingAtTheStartIsAFailureNotAThrow) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 8);
  CalibrationProblem p = power_problem(x, sample(x, truth, 0.0, 0));
  p.model = [](const Eigen::VectorXd&) { return ModelOutput{{}, false, "no contact", ""}; };
  const CalibrationResult r = calibrate(p, {});
  EXPECT_EQ(r.status, CalibrationStatus::kFailed);
  EXPECT_NE(r.reason.find("no contact"), std::string::npos) << r.reason;
  EXPECT_EQ(r.evaluations.total(), 1);
}

// Ctrl-C: the progress callback says stop; the best point so far is kept, no statistics.
TEST(Calibration, InterruptKeepsTheBestPointSoFar) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 20);
  CalibrationSettings s;
  int calls = 0;
  double best = 0;
  s.progress = [&](const CalibrationProgress& pr) {
    ++calls;
    best = pr.best_sse;
    EXPECT_EQ(pr.evaluation, calls);
    return calls < 6;
  };
  const CalibrationResult r = calibrate(power_problem(x, noisy(x, 1)), s);
  EXPECT_EQ(r.status, CalibrationStatus::kInterrupted) << r.reason;
  EXPECT_EQ(r.evaluations.total(), 6);
  EXPECT_FALSE(r.statistics_available);
  EXPECT_DOUBLE_EQ(r.sse, best);
  EXPECT_LE(r.sse, r.sse_start);
}

TEST(Calibration, RejectsInconsistentProblems) {
  const Eigen::VectorXd x3 = grid(0.1, 2.0, 3);
  CalibrationProblem p = power_problem(x3, sample(x3, truth, 0.0, 0));
  EXPECT_THROW(calibrate(p, {}), std::invalid_argument);  // 3 points < 2 parameters + 2
  const Eigen::VectorXd x5 = grid(0.1, 2.0, 5);
  p = power_problem(x5, sample(x5, truth, 0.0, 0));
  p.parameters[0].lower = 2000.0;  // inverted bounds
  EXPECT_THROW(calibrate(p, {}), std::invalid_argument);
  p = power_problem(x5, sample(x5, truth, 0.0, 0));
  p.parameters[1].start = 5.0;  // outside its bounds
  EXPECT_THROW(calibrate(p, {}), std::invalid_argument);
  p = power_problem(x5, sample(x5, truth, 0.0, 0));
  p.weights = Eigen::VectorXd::Constant(5, -1.0);
  EXPECT_THROW(calibrate(p, {}), std::invalid_argument);
}

// A point with weight 0 does not count: the optimum equals the one without that point.
TEST(Calibration, ZeroWeightRemovesAPoint) {
  const Eigen::VectorXd x = grid(0.1, 2.0, 12);
  Eigen::VectorXd y = noisy(x, 9);
  y[5] *= 1.5;  // an outlier
  CalibrationProblem with = power_problem(x, y);
  with.weights = Eigen::VectorXd::Ones(12);
  with.weights[5] = 0.0;
  Eigen::VectorXd xr(11), yr(11);
  xr << x.head(5), x.tail(6);
  yr << y.head(5), y.tail(6);
  const CalibrationResult a = calibrate(with, {});
  const CalibrationResult b = calibrate(power_problem(xr, yr), {});
  for (int j = 0; j < 2; ++j)
    EXPECT_NEAR(a.parameters[j], b.parameters[j], 1e-4 * b.std_errors[j] + 1e-6);
}

}  // namespace
}  // namespace si::fit
