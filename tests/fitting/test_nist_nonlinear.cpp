// NIST StRD nonlinear regression problems (https://www.itl.nist.gov/div898/strd/nls/nls_main.shtml)
// from both of NIST's starting points. Acceptance (issue 6): the certified parameters to 6
// significant digits. The certified standard deviations and residual sum of squares are checked
// to the same 6 digits (they follow from the parameters and the Jacobian at the solution).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "../verification_record.hpp"
#include "fitting/builtin_models.hpp"
#include "fitting/curve_model.hpp"
#include "fitting/nlopt_status.hpp"
#include "fitting/nonlinear_fit.hpp"
#include "fitting_test_support.hpp"

namespace si::fit {
namespace {

using testing::agreeing_digits;
using testing::read_strd;
using testing::StrdProblem;

constexpr double kDigits = 6.0;  // issue 6 acceptance

// Misra1a: y = b1 (1 - exp(-b2 x)).
CurveModel misra1a() {
  CurveModel m;
  m.name = "Misra1a";
  m.parameter_names = {"b1", "b2"};
  m.value = [](double x, const Eigen::VectorXd& b) { return b[0] * (1.0 - std::exp(-b[1] * x)); };
  m.gradient = [](double x, const Eigen::VectorXd& b, Eigen::Ref<Eigen::VectorXd> g) {
    g[0] = 1.0 - std::exp(-b[1] * x);
    g[1] = b[0] * x * std::exp(-b[1] * x);
  };
  return m;
}

// Chwirut2: y = exp(-b1 x) / (b2 + b3 x).
CurveModel chwirut2() {
  CurveModel m;
  m.name = "Chwirut2";
  m.parameter_names = {"b1", "b2", "b3"};
  m.value = [](double x, const Eigen::VectorXd& b) {
    return std::exp(-b[0] * x) / (b[1] + b[2] * x);
  };
  m.gradient = [](double x, const Eigen::VectorXd& b, Eigen::Ref<Eigen::VectorXd> g) {
    const double e = std::exp(-b[0] * x);
    const double d = b[1] + b[2] * x;
    g[0] = -x * e / d;
    g[1] = -e / (d * d);
    g[2] = -x * e / (d * d);
  };
  return m;
}

// Thurber: y = (b1 + b2 x + b3 x^2 + b4 x^3) / (1 + b5 x + b6 x^2 + b7 x^3).
CurveModel thurber() {
  CurveModel m;
  m.name = "Thurber";
  m.parameter_names = {"b1", "b2", "b3", "b4", "b5", "b6", "b7"};
  m.value = [](double x, const Eigen::VectorXd& b) {
    return (b[0] + x * (b[1] + x * (b[2] + x * b[3]))) / (1.0 + x * (b[4] + x * (b[5] + x * b[6])));
  };
  m.gradient = [](double x, const Eigen::VectorXd& b, Eigen::Ref<Eigen::VectorXd> g) {
    const double num = b[0] + x * (b[1] + x * (b[2] + x * b[3]));
    const double den = 1.0 + x * (b[4] + x * (b[5] + x * b[6]));
    for (int k = 0; k < 4; ++k) g[k] = std::pow(x, k) / den;
    for (int k = 1; k < 4; ++k) g[3 + k] = -std::pow(x, k) * num / (den * den);
  };
  return m;
}

struct Case {
  std::string file;
  CurveModel (*model)();
  bool analytic_jacobian;
};

void expect_certified(const StrdProblem& p, const FitResult& r, const std::string& what) {
  ASSERT_EQ(r.status, FitStatus::kConverged) << what << ": " << r.reason;
  for (Eigen::Index j = 0; j < p.certified.size(); ++j) {
    EXPECT_GE(agreeing_digits(r.parameters[j], p.certified[j]), kDigits)
        << what << " " << p.names[j] << " = " << r.parameters[j] << ", certified "
        << p.certified[j];
    si::test::record_verification("nist-strd", what + " " + p.names[j], p.certified[j],
                                  r.parameters[j], std::pow(10.0, -kDigits),
                                  "NIST StRD certified values (11 digits)");
    EXPECT_GE(agreeing_digits(r.std_errors[j], p.certified_sd[j]), kDigits)
        << what << " sd(" << p.names[j] << ") = " << r.std_errors[j] << ", certified "
        << p.certified_sd[j];
  }
  EXPECT_GE(agreeing_digits(r.sse, p.stats.at("rss")), kDigits) << what << " SSE " << r.sse;
  EXPECT_GE(agreeing_digits(r.residual_std_dev, p.stats.at("rsd")), kDigits) << what;
}

std::string case_name(const ::testing::TestParamInfo<Case>& c) {
  return c.param.file.substr(0, c.param.file.find('.')) +
         (c.param.analytic_jacobian ? "_Analytic" : "_FiniteDifferences");
}

class NistNonlinear : public ::testing::TestWithParam<Case> {};

TEST_P(NistNonlinear, CertifiedValuesFromBothStarts) {
  const Case& c = GetParam();
  const StrdProblem p = read_strd(c.file);
  CurveModel model = c.model();
  if (!c.analytic_jacobian) model.gradient = nullptr;
  for (int start = 1; start <= 2; ++start) {
    FitSettings s;
    s.start = start == 1 ? p.start1 : p.start2;
    const FitResult r = fit(curve_problem(model, p.x, p.y), s);
    expect_certified(p, r, model.name + " start " + std::to_string(start));
    EXPECT_EQ(r.evaluations.finite_differences, !c.analytic_jacobian);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Strd, NistNonlinear,
    ::testing::Values(Case{"misra1a.txt", misra1a, true}, Case{"chwirut2.txt", chwirut2, true},
                      Case{"thurber.txt", thurber, true},
                      Case{"misra1a.txt", misra1a, false},  // finite-difference Jacobian
                      Case{"thurber.txt", thurber, false}),
    case_name);

// DanWood (NIST StRD, lower difficulty) is a power law y = b1 x^b2: the built-in power model,
// from NIST's starts and from its own guessed starting values.
TEST(NistNonlinear, DanWood_BuiltinPowerLaw) {
  const StrdProblem p = read_strd("danwood.txt");
  for (int start = 0; start <= 2; ++start) {
    FitSettings s;
    if (start > 0) s.start = start == 1 ? p.start1 : p.start2;
    expect_certified(p, fit_curve(power_law(), p.x, p.y, s),
                     "DanWood start " + std::to_string(start));
  }
}

// Issue 18: NLopt itself finds the optimum. On every set, from both of NIST's starts, with the
// analytic and the finite-difference Jacobian: the gradient stage (LD_SLSQP) ends with a success
// code, no derivative-free fallback runs, and NLopt's own result - before the Levenberg-Marquardt
// polish - already agrees with the certified values to 6 digits. The polished result is checked
// as well (both are reported; docs/fitting.md's table is these lines).
struct NloptCase {
  std::string file;
  CurveModel (*model)();
};

class NistNlopt : public ::testing::TestWithParam<NloptCase> {};

double min_digits(const Eigen::VectorXd& c, const StrdProblem& p) {
  double d = 16.0;
  for (Eigen::Index j = 0; j < p.certified.size(); ++j)
    d = std::min(d, agreeing_digits(c[j], p.certified[j]));
  return d;
}

TEST_P(NistNlopt, GradientStageFindsTheOptimumWithoutFailureCode) {
  const StrdProblem p = read_strd(GetParam().file);
  for (const bool analytic : {true, false}) {
    CurveModel model = GetParam().model();
    if (!analytic) model.gradient = nullptr;
    for (int start = 1; start <= 2; ++start) {
      FitSettings s;
      s.start = start == 1 ? p.start1 : p.start2;
      const FitResult r = fit(curve_problem(model, p.x, p.y), s);
      const std::string what = GetParam().file + " start " + std::to_string(start) +
                               (analytic ? " analytic" : " finite differences");
      const double nlopt_digits = min_digits(r.nlopt_parameters, p);
      const double polished_digits = min_digits(r.parameters, p);
      std::printf(
          "[nist] %s: %s code %d (%s), %d residual evaluations; digits NLopt %.1f, "
          "polished %.1f\n",
          what.c_str(), r.nlopt_algorithm.c_str(), r.nlopt_code,
          nlopt_code_name(r.nlopt_code).c_str(), r.evaluations.residuals, nlopt_digits,
          polished_digits);
      EXPECT_GT(r.nlopt_code, 0) << what << ": " << r.reason;
      EXPECT_FALSE(r.nlopt_fallback) << what << ": " << r.reason;
      EXPECT_EQ(r.nlopt_algorithm, "LD_SLSQP") << what;
      EXPECT_GE(nlopt_digits, kDigits) << what << ": NLopt alone";
      EXPECT_GE(polished_digits, kDigits) << what << ": polished";
      if (analytic)
        for (Eigen::Index j = 0; j < p.certified.size(); ++j)
          si::test::record_verification("nist-strd", what + " " + p.names[j] + ", NLopt alone",
                                        p.certified[j], r.nlopt_parameters[j],
                                        std::pow(10.0, -kDigits),
                                        "NIST StRD certified values (11 digits)");
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Strd, NistNlopt,
                         ::testing::Values(NloptCase{"misra1a.txt", misra1a},
                                           NloptCase{"chwirut2.txt", chwirut2},
                                           NloptCase{"thurber.txt", thurber},
                                           NloptCase{"danwood.txt", power_law}),
                         [](const ::testing::TestParamInfo<NloptCase>& c) {
                           return c.param.file.substr(0, c.param.file.find('.'));
                         });

// The derivative-free algorithm on its own (LN_BOBYQA, no polish): never a failure code, and the
// certified values to 6 digits except from Thurber's start 1, where 7 parameters of a rational
// function are beyond BOBYQA's 5000 evaluations (it stops with MAXEVAL_REACHED, reported as
// "stalled" - not a failure code, not a solution either).
TEST(NistNonlinear, DerivativeFreeAloneNeverReturnsAFailureCode) {
  const NloptCase sets[] = {{"misra1a.txt", misra1a},
                            {"chwirut2.txt", chwirut2},
                            {"thurber.txt", thurber},
                            {"danwood.txt", power_law}};
  for (const NloptCase& set : sets) {
    const StrdProblem p = read_strd(set.file);
    for (int start = 1; start <= 2; ++start) {
      FitSettings s;
      s.start = start == 1 ? p.start1 : p.start2;
      s.method = Method::kDerivativeFree;
      s.polish_iterations = 0;
      const FitResult r = fit(curve_problem(set.model(), p.x, p.y), s);
      const std::string what = set.file + " start " + std::to_string(start);
      const double digits = min_digits(r.nlopt_parameters, p);
      std::printf("[nist] %s: LN_BOBYQA code %d (%s), %d evaluations, digits %.1f\n", what.c_str(),
                  r.nlopt_code, nlopt_code_name(r.nlopt_code).c_str(), r.evaluations.residuals,
                  digits);
      EXPECT_GT(r.nlopt_code, 0) << what << ": " << r.reason;
      EXPECT_EQ(r.nlopt_algorithm, "LN_BOBYQA");
      if (set.file == "thurber.txt" && start == 1)
        EXPECT_EQ(r.nlopt_code, nlopt::MAXEVAL_REACHED) << what;
      else
        EXPECT_GE(digits, kDigits) << what;
    }
  }
}

// The derivative-free path alone (LN_BOBYQA, then the polish) also reaches Misra1a's values.
TEST(NistNonlinear, Misra1a_DerivativeFreeMethod) {
  const StrdProblem p = read_strd("misra1a.txt");
  FitSettings s;
  s.start = p.start1;
  s.method = Method::kDerivativeFree;
  const FitResult r = fit(curve_problem(misra1a(), p.x, p.y), s);
  expect_certified(p, r, "Misra1a derivative-free");
  EXPECT_NE(r.method.find("BOBYQA"), std::string::npos) << r.method;
}

}  // namespace
}  // namespace si::fit
