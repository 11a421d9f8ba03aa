#include "contact/ncp_function.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace si {
namespace {

TEST(NcpFunction, ZeroExactlyOnTheComplementaritySet) {
  for (NcpFunction f : {NcpFunction::kFischerBurmeister, NcpFunction::kMin}) {
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

}  // namespace
}  // namespace si
