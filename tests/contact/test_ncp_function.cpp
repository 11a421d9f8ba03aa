#include "contact/ncp_function.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace si {
namespace {

TEST(NcpFunction, ZeroExactlyOnTheComplementaritySet) {
  for (NcpFunction f :
       {NcpFunction::kFischerBurmeister, NcpFunction::kMin, NcpFunction::kFischerBurmeisterMin}) {
    EXPECT_EQ(ncp(f, 0.0, 3.0).value, 0.0);
    EXPECT_EQ(ncp(f, 5.0, 0.0).value, 0.0);
    EXPECT_EQ(ncp(f, 0.0, 0.0).value, 0.0);
    EXPECT_NE(ncp(f, 1.0, 1.0).value, 0.0);
    EXPECT_LT(ncp(f, -1.0, 2.0).value, 0.0);
    EXPECT_LT(ncp(f, 2.0, -1.0).value, 0.0);
  }
}

// The stable form keeps full relative accuracy where a + b - r cancels: for a >> b > 0,
// phi = b - b^2 / (2a) + O(b^3 / a^2).
TEST(NcpFunction, FischerBurmeisterAccurateForLargeMultiplierAndTinyGap) {
  const double a = 1e4, b = 1e-9;
  EXPECT_NEAR(ncp(NcpFunction::kFischerBurmeister, a, b).value, b - b * b / (2 * a), 1e-24);
}

TEST(NcpFunction, FischerBurmeisterDerivativesMatchFiniteDifferences) {
  const double h = 1e-7;
  for (const auto& [a, b] : {std::pair{0.3, 1.7}, {-0.4, 0.9}, {2.0, -0.5}}) {
    const NcpValue v = ncp(NcpFunction::kFischerBurmeister, a, b);
    const auto phi = [](double x, double y) {
      return ncp(NcpFunction::kFischerBurmeister, x, y).value;
    };
    EXPECT_NEAR(v.d_a, (phi(a + h, b) - phi(a - h, b)) / (2 * h), 1e-7);
    EXPECT_NEAR(v.d_b, (phi(a, b + h) - phi(a, b - h)) / (2 * h), 1e-7);
  }
}

// The default of the KINSOL runs: FB where a >= 0 and b >= 0, min elsewhere.
TEST(NcpFunction, FischerBurmeisterMinIsFischerBurmeisterWhereFeasibleAndMinElsewhere) {
  const auto value = [](NcpFunction f, double a, double b) { return ncp(f, a, b).value; };
  const NcpFunction hybrid = NcpFunction::kFischerBurmeisterMin;
  for (const auto& [a, b] : {std::pair{0.3, 1.7}, {2.0, 0.5}, {0.0, 0.0}, {1e4, 1e-9}})
    EXPECT_EQ(value(hybrid, a, b), value(NcpFunction::kFischerBurmeister, a, b)) << a << " " << b;
  for (const auto& [a, b] : {std::pair{-0.4, 0.9}, {2.0, -0.5}, {-1.0, -3.0}, {0.0, -2.0}})
    EXPECT_EQ(value(hybrid, a, b), value(NcpFunction::kMin, a, b)) << a << " " << b;
}

// Its reason: from (0, -B), a candidate pushed through the indenter with no force, the Newton
// step of min closes the linearised gap whatever the coupling, FB's does not (ncp_function.hpp):
// for a node with b = -B + c a, Newton gives a = B / c (min) and a = 2B / (1 + 2c) (FB).
TEST(NcpFunction, FischerBurmeisterMinStepRecoversTheContactForceFromAnInfeasiblePrediction) {
  const double B = 1.0, c = 1.0;
  const auto newton_a = [&](NcpFunction f) {  // a_1 from a_0 = 0, b_0 = -B
    const NcpValue v = ncp(f, 0.0, -B);
    return -v.value / (v.d_a + v.d_b * c);
  };
  EXPECT_DOUBLE_EQ(newton_a(NcpFunction::kFischerBurmeisterMin), B / c);
  EXPECT_DOUBLE_EQ(newton_a(NcpFunction::kFischerBurmeister), 2 * B / (1 + 2 * c));
}

// Continuously differentiable across the edges of the feasible quadrant: the one-sided
// gradients agree on a = 0 < b and on b = 0 < a (and the derivatives match finite differences
// inside each piece).
TEST(NcpFunction, FischerBurmeisterMinIsC1AcrossTheQuadrantEdgesAndItsDerivativesAreExact) {
  const NcpFunction f = NcpFunction::kFischerBurmeisterMin;
  const double e = 1e-12;
  for (const auto& [a, b] : {std::pair{0.0, 2.0}, {1.5, 0.0}}) {
    const NcpValue inside = ncp(f, a + (a == 0 ? e : 0), b + (b == 0 ? e : 0));
    const NcpValue outside = ncp(f, a - (a == 0 ? e : 0), b - (b == 0 ? e : 0));
    EXPECT_NEAR(inside.d_a, outside.d_a, 1e-9) << a << " " << b;
    EXPECT_NEAR(inside.d_b, outside.d_b, 1e-9) << a << " " << b;
    EXPECT_NEAR(inside.value, outside.value, 1e-11);
  }
  const double h = 1e-7;
  const auto phi = [f](double x, double y) { return ncp(f, x, y).value; };
  for (const auto& [a, b] : {std::pair{0.3, 1.7}, {-0.4, 0.9}, {2.0, -0.5}, {-1.0, -3.0}}) {
    const NcpValue v = ncp(f, a, b);
    EXPECT_NEAR(v.d_a, (phi(a + h, b) - phi(a - h, b)) / (2 * h), 1e-7);
    EXPECT_NEAR(v.d_b, (phi(a, b + h) - phi(a, b - h)) / (2 * h), 1e-7);
  }
}

}  // namespace
}  // namespace si
