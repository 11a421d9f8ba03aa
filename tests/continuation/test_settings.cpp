// Settings validation: bad settings are rejected with a message naming the field and value.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "continuation/settings.hpp"

namespace si::cont {
namespace {

// Expects validate() to throw std::invalid_argument whose message contains `expected`.
void expect_rejected(const std::function<void(Settings&)>& spoil, const std::string& expected) {
  Settings settings;
  spoil(settings);
  try {
    settings.validate();
    ADD_FAILURE() << "accepted; expected an error containing: " << expected;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
        << "message: " << e.what() << "\nexpected to contain: " << expected;
  }
}

TEST(ContSettings, DefaultsAreValid) {
  EXPECT_NO_THROW(Settings{}.validate());
}

TEST(ContSettings, RejectsMinStepAboveMaxStep) {
  expect_rejected(
      [](Settings& s) {
        s.step_min = 2;
        s.step_max = 1;
        s.step_initial = 1;
      },
      "continuation.step_min = 2 > step_max = 1");
}

TEST(ContSettings, RejectsNegativeOrZeroSteps) {
  expect_rejected([](Settings& s) { s.step_min = -1e-3; }, "continuation.step_min = -0.001");
  expect_rejected([](Settings& s) { s.step_max = 0; }, "continuation.step_max = 0");
  expect_rejected([](Settings& s) { s.step_initial = 5; },
                  "continuation.step_initial = 5 is outside [step_min, step_max]");
}

TEST(ContSettings, RejectsBadBoundsAndCounts) {
  expect_rejected(
      [](Settings& s) {
        s.p_min = 2;
        s.p_max = 1;
      },
      "continuation.p_min = 2 must be < p_max = 1");
  expect_rejected([](Settings& s) { s.max_steps = -3; }, "continuation.max_steps = -3");
  expect_rejected([](Settings& s) { s.direction = 0; }, "continuation.direction = 0");
  expect_rejected([](Settings& s) { s.event_tolerance = -1; }, "continuation.event_tolerance");
  expect_rejected([](Settings& s) { s.checkpoint_interval = 5; }, "needs a checkpoint_path");
}

TEST(ContSettings, RejectsNaturalCorrectorSlopeOutsideZeroToOne) {
  expect_rejected([](Settings& s) { s.natural_corrector_slope = 1.0; },
                  "continuation.natural_corrector_slope = 1");
  expect_rejected([](Settings& s) { s.natural_corrector_slope = -0.5; },
                  "continuation.natural_corrector_slope = -0.5");
  expect_rejected([](Settings& s) { s.natural_corrector_slope = std::nan(""); },
                  "continuation.natural_corrector_slope = nan");
}

TEST(ContSettings, RejectsLandingStretchOutsideZeroToOne) {
  expect_rejected([](Settings& s) { s.landing_stretch = -0.1; },
                  "continuation.landing_stretch = -0.1");
  expect_rejected([](Settings& s) { s.landing_stretch = 2.0; }, "continuation.landing_stretch = 2");
  expect_rejected([](Settings& s) { s.landing_stretch = std::nan(""); },
                  "continuation.landing_stretch = nan");
}

TEST(ContSettings, RejectsBadStabilityAndFeatureSettings) {
  expect_rejected([](Settings& s) { s.stability_modes = -1; },
                  "continuation.stability_modes = -1 must be >= 0");
  expect_rejected([](Settings& s) { s.feature_refinement = 0; },
                  "continuation.feature_refinement = 0 must be >= 1");
  expect_rejected([](Settings& s) { s.feature_noise_factor = 0; },
                  "continuation.feature_noise_factor = 0 must be positive");
  expect_rejected([](Settings& s) { s.feature_curvature_tolerance = -1e-3; },
                  "continuation.feature_curvature_tolerance = -0.001 must be >= 0");
}

TEST(ContSettings, RejectsBadNewtonSettings) {
  expect_rejected([](Settings& s) { s.newton.relative_tolerance = 0; },
                  "continuation.newton.relative_tolerance = 0");
  expect_rejected([](Settings& s) { s.newton.max_iterations = 0; },
                  "continuation.newton.max_iterations = 0");
  expect_rejected([](Settings& s) { s.newton.residual_scale = 0; },
                  "continuation.newton.residual_scale = 0");
  expect_rejected([](Settings& s) { s.newton.stall_window = -1; },
                  "continuation.newton.stall_window = -1");
  expect_rejected([](Settings& s) { s.newton.stall_ratio = 1.0; },
                  "continuation.newton.stall_ratio = 1");
  NewtonSettings newton;
  newton.residual_scale = 0;  // allowed for a standalone solve: purely relative
  EXPECT_NO_THROW(newton.validate());
}

TEST(ContSettings, RejectsParameterValuesNotIncreasingOrNotFinite) {
  expect_rejected(
      [](Settings& s) {
        s.method = Method::kNatural;
        s.parameter_values = {0.1, 0.3, 0.2};
      },
      "continuation.parameter_values[2] = 0.20000000000000001 must be greater");
  expect_rejected(
      [](Settings& s) {
        s.parameter_values = {0.1, INFINITY};
      },
      "continuation.parameter_values[1] = inf must be finite");
  Settings arclength;  // pseudo_arclength lands on them (test_landing.cpp)
  arclength.parameter_values = {0.1};
  EXPECT_NO_THROW(arclength.validate());
}

TEST(ContSettings, RejectsUnknownMethodAndPredictorNames) {
  EXPECT_EQ(parse_method("natural"), Method::kNatural);
  EXPECT_EQ(parse_method("pseudo_arclength"), Method::kPseudoArclength);
  EXPECT_EQ(parse_predictor("secant"), Predictor::kSecant);
  try {
    parse_method("arc-length");
    ADD_FAILURE() << "unknown method accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "continuation.method = 'arc-length' is unknown (expected natural | "
                 "pseudo_arclength)");
  }
  EXPECT_THROW(parse_predictor("euler"), std::invalid_argument);
}

}  // namespace
}  // namespace si::cont
