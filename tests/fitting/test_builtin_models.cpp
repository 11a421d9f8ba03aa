// The built-in models (power law in linear and log space, Hertz, power law with offset,
// polynomials) against synthetic data. Acceptance (issue 6): noise-free data give back the
// parameters to 1e-8; on noisy data the 95 % intervals cover the true parameters in at least 90
// of 100 seeded trials (each parameter separately; the nominal rate is 95).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "fitting/builtin_models.hpp"
#include "fitting/linear_fit.hpp"
#include "synthetic_data.hpp"

namespace si::fit {
namespace {

using testing::grid;
using testing::max_relative_error;
using testing::sample;

constexpr double kRecovery = 1e-8;
constexpr int kTrials = 100;
constexpr int kMinCovered = 90;

using Fitter = std::function<FitResult(const Eigen::VectorXd& x, const Eigen::VectorXd& y)>;

// Counts, per parameter, the trials whose interval contains the truth.
void expect_coverage(const Fitter& fitter, const Eigen::VectorXd& x,
                     const std::function<double(double)>& truth_curve, const Eigen::VectorXd& truth,
                     double sigma, bool log_noise = false) {
  Eigen::VectorXi covered = Eigen::VectorXi::Zero(truth.size());
  for (int seed = 1; seed <= kTrials; ++seed) {
    Eigen::VectorXd y = sample(
        x, [](double) { return 0.0; }, sigma, seed);
    for (Eigen::Index i = 0; i < x.size(); ++i)
      y[i] = log_noise ? truth_curve(x[i]) * std::exp(y[i]) : truth_curve(x[i]) + y[i];
    const FitResult r = fitter(x, y);
    ASSERT_EQ(r.status, FitStatus::kConverged) << "seed " << seed << ": " << r.reason;
    for (Eigen::Index j = 0; j < truth.size(); ++j)
      covered[j] += r.ci_lower[j] <= truth[j] && truth[j] <= r.ci_upper[j];
  }
  for (Eigen::Index j = 0; j < truth.size(); ++j) {
    ::testing::Test::RecordProperty("covered_" + std::to_string(j), covered[j]);
    EXPECT_GE(covered[j], kMinCovered) << "parameter " << j << " covered " << covered[j] << "/100";
  }
}

const Eigen::Vector2d kPower{350.0, 1.37};  // T = C1 h^C2, N and mm
double power_curve(double x) {
  return kPower[0] * std::pow(x, kPower[1]);
}

TEST(BuiltinModels, PowerLaw_NoiseFreeRecovery) {
  const Eigen::VectorXd x = grid(0.0, 2.0, 25);  // from zero depth, as a force-depth path
  const Eigen::VectorXd y = sample(x, power_curve, 0.0, 0);
  for (const bool own_start : {true, false}) {
    FitSettings s;
    if (!own_start) s.start = Eigen::Vector2d(1.0, 1.0);
    const FitResult r = fit_curve(power_law(), x, y, s);
    ASSERT_EQ(r.status, FitStatus::kConverged) << r.reason;
    EXPECT_LT(max_relative_error(r.parameters, kPower), kRecovery) << r.parameters.transpose();
    EXPECT_NEAR(r.r_squared, 1.0, 1e-14);
  }
}

TEST(BuiltinModels, PowerLaw_Coverage) {
  expect_coverage([](const auto& x, const auto& y) { return fit_curve(power_law(), x, y); },
                  grid(0.05, 2.0, 30), power_curve, kPower, 20.0);
}

TEST(BuiltinModels, PowerLawLogSpace_NoiseFreeRecoveryAndCoverage) {
  const Eigen::VectorXd x = grid(0.05, 2.0, 30);
  const FitResult r = fit_power_law_log(x, sample(x, power_curve, 0.0, 0));
  EXPECT_LT(max_relative_error(r.parameters, kPower), kRecovery) << r.parameters.transpose();
  // Multiplicative noise, the error model under which the log-space fit is the right one.
  expect_coverage([](const auto& xs, const auto& ys) { return fit_power_law_log(xs, ys); }, x,
                  power_curve, kPower, 0.05, true);
  EXPECT_THROW(fit_power_law_log(grid(0.0, 1.0, 5), grid(1.0, 2.0, 5)), std::invalid_argument);
}

TEST(BuiltinModels, Hertz_NoiseFreeRecoveryAndCoverage) {
  const Eigen::VectorXd truth = Eigen::VectorXd::Constant(1, 812.5);
  const auto curve = [&](double x) { return truth[0] * std::pow(x, 1.5); };
  const Eigen::VectorXd x = grid(0.0, 1.0, 20);
  const FitResult r = fit_curve(hertz_law(), x, sample(x, curve, 0.0, 0));
  EXPECT_LT(max_relative_error(r.parameters, truth), kRecovery);
  expect_coverage([](const auto& xs, const auto& ys) { return fit_curve(hertz_law(), xs, ys); }, x,
                  curve, truth, 15.0);
}

TEST(BuiltinModels, PowerLawWithOffset_NoiseFreeRecoveryAndCoverage) {
  const Eigen::Vector3d truth{50.0, 1.6, 3.0};  // C1, C2, C0
  const auto curve = [&](double x) { return truth[0] * std::pow(x, truth[1]) + truth[2]; };
  const Eigen::VectorXd x = grid(0.0, 3.0, 40);
  const FitResult r = fit_curve(power_law_with_offset(), x, sample(x, curve, 0.0, 0));
  ASSERT_EQ(r.status, FitStatus::kConverged) << r.reason;
  EXPECT_LT(max_relative_error(r.parameters, truth), kRecovery) << r.parameters.transpose();
  expect_coverage(
      [](const auto& xs, const auto& ys) { return fit_curve(power_law_with_offset(), xs, ys); }, x,
      curve, truth, 2.0);
}

// C1 or C2 as a cubic in the lay-up angle (deg), the users' second kind of fit.
TEST(BuiltinModels, CubicInAngle_NoiseFreeRecoveryAndCoverage) {
  const Eigen::Vector4d truth{2.0, -0.03, 4e-4, -2e-6};
  const auto curve = [&](double a) {
    return truth[0] + a * (truth[1] + a * (truth[2] + a * truth[3]));
  };
  const Eigen::VectorXd angle = grid(0.0, 90.0, 19);
  const FitResult r = fit_polynomial(angle, sample(angle, curve, 0.0, 0), 3);
  EXPECT_LT(max_relative_error(r.parameters, truth), kRecovery) << r.parameters.transpose();
  expect_coverage([](const auto& xs, const auto& ys) { return fit_polynomial(xs, ys, 3); }, angle,
                  curve, truth, 0.01);
}

TEST(BuiltinModels, PowerLawRejectsNegativeDepth) {
  EXPECT_THROW(fit_curve(power_law(), grid(-1.0, 1.0, 5), grid(0.0, 1.0, 5)),
               std::invalid_argument);
}

}  // namespace
}  // namespace si::fit
