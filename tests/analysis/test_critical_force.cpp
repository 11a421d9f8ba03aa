#include "analysis/critical_force.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace si {
namespace {

// Points of T = (k - 0.3)^3 + 2 k against k = depth / 10: one inflection at k = 0.3 (depth 3).
std::vector<PathPoint> cubic_path(double noise_at = -1) {
  std::vector<PathPoint> pts;
  for (int i = 0; i <= 60; ++i) {
    PathPoint p;
    p.state.depth = 0.1 * i;
    const double k = p.state.depth / 10;
    p.state.apex_curvature = Vector3d(k, 0, 2 * k);
    p.state.force = std::pow(k - 0.3, 3) + 2 * k;
    if (std::abs(p.state.depth - noise_at) < 1e-9) p.state.force += 1e-3;  // a one-point kink
    pts.push_back(p);
  }
  return pts;
}

TEST(CriticalForce, FindsTheInflectionOfACubic) {
  for (int curvature : {0, 2}) {
    const auto events = critical_force_events(cubic_path(), curvature);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_NEAR(events[0].p, 3.0, 0.1);  // within the bracket of two points
    EXPECT_EQ(events[0].against, curvature == 0 ? "k11_per_mm" : "k22_per_mm");
    EXPECT_FALSE(events[0].located);
  }
}

// A kink at one point (a contact change) flips the discrete second derivative at two points
// only: not an inflection.
TEST(CriticalForce, IgnoresOnePointKinks) {
  const auto events = critical_force_events(cubic_path(1.0), 0);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NEAR(events[0].p, 3.0, 0.1);
}

}  // namespace
}  // namespace si
