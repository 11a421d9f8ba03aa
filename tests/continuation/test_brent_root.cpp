// Brent's method (continuation/brent_root.hpp) on scalar functions with known roots: the root of
// cos x = x (the Dottie number, 0.7390851332151607) and of a cubic with a flat root; the value
// tolerance; a function that cannot be evaluated. The event locator and the critical points'
// onset search both run on it.
#include <gtest/gtest.h>

#include <cmath>

#include "continuation/brent_root.hpp"

namespace si::cont {
namespace {

constexpr double kDottie = 0.7390851332151607;

// Converges superlinearly: the 1e-14 bracket in far fewer evaluations than bisection's 47.
TEST(BrentRoot, DottieNumberToTheBracketInFewerEvaluationsThanBisection) {
  int evaluations = 0;
  const auto f = [&](double x) {
    ++evaluations;
    return std::cos(x) - x;
  };
  const RootBracket<double> r = brent_root(f, 0.0, 1.0, f(0.0), f(1.0), {1e-14, 0.0, 100});
  EXPECT_NEAR(r.best.x, kDottie, 1e-14);
  EXPECT_LE(r.width(), 1e-14);
  EXPECT_LT(evaluations, 15);
  EXPECT_LE(r.best.f * r.other.f, 0.0);  // still a bracket (or an exact zero)
}

// A triple root, where interpolation converges slowly: the bisection safeguard still closes the
// bracket, in at most a few times bisection's count.
TEST(BrentRoot, TripleRootClosedByTheBisectionSafeguard) {
  int evaluations = 0;
  const auto f = [&](double x) {
    ++evaluations;
    return std::pow(x - 0.3, 3);
  };
  const RootBracket<double> r = brent_root(f, -1.0, 2.0, f(-1.0), f(2.0), {1e-12, 0.0, 400});
  EXPECT_NEAR(r.best.x, 0.3, 1e-12);
  EXPECT_LT(evaluations, 3 * 42);
}

// With a value tolerance the search stops once |f| is within it, earlier than the bracket test;
// the secant's distance bounds the true distance to the root there (f is nearly linear).
TEST(BrentRoot, ValueToleranceStopsEarlyWithAnHonestDistance) {
  int strict = 0, loose = 0;
  int* count = &strict;
  const auto f = [&](double x) {
    ++*count;
    return std::cos(x) - x;
  };
  brent_root(f, 0.0, 1.0, 1.0, std::cos(1.0) - 1.0, {1e-15, 0.0, 100});
  count = &loose;
  const RootBracket<double> r =
      brent_root(f, 0.0, 1.0, 1.0, std::cos(1.0) - 1.0, {1e-15, 1e-6, 100});
  EXPECT_LT(loose, strict);
  EXPECT_TRUE(r.within_value(1e-6));
  EXPECT_LE(std::abs(r.best.f), 1e-6);
  const double error = std::abs(r.best.x - kDottie);
  EXPECT_LE(error, 1.5 * r.secant_distance() + 1e-16);
  EXPECT_LE(r.secant_distance(), r.width());
  const RootSearch search{1e-15, 1e-6, 100};
  EXPECT_TRUE(r.converged(search));
  EXPECT_EQ(r.accuracy(search), r.secant_distance());  // the value test stopped it
}

// A NaN ends the search with the bracket so far: never a NaN as the best estimate.
TEST(BrentRoot, UnevaluableFunctionEndsTheSearchWithTheBracketSoFar) {
  int evaluations = 0;
  const auto f = [&](double x) {
    ++evaluations;
    return evaluations > 2 ? std::nan("") : std::cos(x) - x;
  };
  const RootBracket<double> r =
      brent_root(f, 0.0, 1.0, 1.0, std::cos(1.0) - 1.0, {1e-14, 0.0, 100});
  EXPECT_EQ(evaluations, 3);
  EXPECT_FALSE(std::isnan(r.best.f));
  EXPECT_GT(r.width(), 1e-14);
  EXPECT_FALSE(r.converged({1e-14, 0.0, 100}));
  EXPECT_EQ(r.accuracy({1e-14, 0.0, 100}), r.width());
  EXPECT_LE(r.best.x, 1.0);
  EXPECT_GE(r.best.x, 0.0);
}

}  // namespace
}  // namespace si::cont
