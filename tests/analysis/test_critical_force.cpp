// The depth grids' critical force (critical_force.hpp): the inflection of T_N against a
// curvature, reported only where resolved. What it must find (a cubic's inflection) and what it
// must not: an exactly linear segment whose second differences are roundoff (issue 15: a k22
// "inflection" of the linear path, second difference -0.069 between neighbours of +-9e6), and
// kinks where the contact set changes. The old detector (sign changes of the three-point second
// difference persisting 3 points, 46262a4) reported an inflection in each of the last two; the
// tests say so with their inputs.
#include "analysis/critical_force.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../indentation/indentation_test_support.hpp"

namespace si {
namespace {

// A point at `depth` with force T, curvature k (k11 = k, k22 = 2k) and the nodes `set` pressing.
PathPoint point(double depth, double T, double k, const std::vector<int>& set) {
  PathPoint p;
  p.state.depth = depth;
  p.state.force = T;
  p.state.apex_curvature = Vector3d(k, 0, 2 * k);
  for (int n : set) {
    p.state.nodes.push_back(n);
    p.state.multipliers.push_back(1.0);
  }
  return p;
}

// The old detector (46262a4): the signs of the three-point second difference of T(k), zeros
// skipped, and a change reported where 3 equal signs are followed by 3 opposite ones.
bool old_detector_reports(const std::vector<PathPoint>& pts, int curvature = 0) {
  std::vector<int> s;
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    const double x0 = pts[i - 1].state.apex_curvature[curvature],
                 x1 = pts[i].state.apex_curvature[curvature],
                 x2 = pts[i + 1].state.apex_curvature[curvature];
    const double y0 = pts[i - 1].state.force, y1 = pts[i].state.force, y2 = pts[i + 1].state.force;
    const double d2 = (y2 - y1) / (x2 - x1) - (y1 - y0) / (x1 - x0);
    if (d2 != 0) s.push_back(d2 > 0 ? 1 : -1);
  }
  for (std::size_t j = 2; j + 3 < s.size(); ++j)
    if (s[j - 2] == s[j] && s[j - 1] == s[j] && s[j + 1] == -s[j] && s[j + 2] == -s[j] &&
        s[j + 3] == -s[j])
      return true;
  return false;
}

// T = (k - 0.3)^3 + 2 k against k = depth / 10 on one contact set: one inflection at k = 0.3.
TEST(CriticalForce, FindsTheInflectionOfACubic) {
  std::vector<PathPoint> pts;
  for (int i = 0; i <= 60; ++i) {
    const double k = 0.01 * i;
    pts.push_back(point(0.1 * i, std::pow(k - 0.3, 3) + 2 * k, k, {1, 2}));
  }
  for (int curvature : {0, 2}) {
    const auto events = critical_force_events(pts, curvature);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_NEAR(events[0].p, 3.0, 1e-6);  // g is linear in the depth here: exact
    EXPECT_EQ(events[0].against, curvature == 0 ? "k11_per_mm" : "k22_per_mm");
    EXPECT_FALSE(events[0].located);
  }
}

// An exactly linear segment (T = 9e3 h, k = 0.02 h) with roundoff in T shaped so that the second
// difference is + for 4 points then - for 4 (2.7e-8 N, 3e-12 of T's scale): the old detector
// reported it.
TEST(CriticalForce, NoInflectionInsideAnExactlyLinearSegment) {
  const int d2[] = {1, 1, 1, 1, -1, -1, -1, -1};
  std::vector<double> noise = {0.0, 0.0};
  for (int s : d2) noise.push_back(2 * noise.back() - noise[noise.size() - 2] + s);
  std::vector<PathPoint> pts;
  for (std::size_t i = 0; i < noise.size(); ++i) {
    const double h = 0.1 * static_cast<double>(i + 1);
    pts.push_back(point(h, 9e3 * h + 2.7e-8 * noise[i], 0.02 * h, {4, 5, 6}));
  }
  ASSERT_TRUE(old_detector_reports(pts));
  EXPECT_TRUE(critical_force_events(pts, 0).empty());
  EXPECT_TRUE(critical_force_events(pts, 2).empty());
}

// A polyline of straight pieces (the linear path is straight on each contact set) whose slope
// rises at three kinks and falls at three, a node entering contact at each (binary-exact values:
// no roundoff inside the pieces). The old detector saw + + + - - - at the kinks and reported an
// inflection; the kinks are contact events, and nothing is an inflection.
TEST(CriticalForce, KinksWhereNodesEnterContactAreNotInflections) {
  const double slopes[] = {1, 2, 3, 4, 3.5, 3, 2.5};  // per piece of 4 steps
  std::vector<PathPoint> pts = {point(0, 0, 0, {0})};
  std::vector<int> set = {0};
  double T = 0, k = 0;
  for (int piece = 0; piece < 7; ++piece) {
    for (int j = 0; j < 4; ++j) {
      k += 0.25;
      T += slopes[piece] * 0.25;
      pts.push_back(point(static_cast<double>(pts.size()) * 0.5, T, k, set));
    }
    set.push_back(piece + 1);
  }
  ASSERT_TRUE(old_detector_reports(pts));
  EXPECT_TRUE(critical_force_events(pts, 0).empty());
}

// The paper's cap on a 1.25 mm quarter mesh, [0/90]2S (issue 15's cases).
CaseFile cap_125(const std::string& kinematics, double depth_max) {
  CaseFile c = testing::coarse_cap_case(kinematics, "[0/90]2S", "quarter", 1.25, 2.5);
  c.path.depth_max = depth_max;
  c.path.step = 0.1;
  c.path.step_max = 1.0;
  return c;
}

int inflections(const PathResult& r) {
  int n = 0;
  for (const cont::Event& e : r.events) n += e.type == cont::EventType::kInflection;
  return n;
}

// The linear path (fast path, 0.1 mm grid to 10 mm): the old detector reported two k22
// "inflections" (5.95 and 6.35 mm) where T_N and k22 are straight between contact changes. Those
// came from the roundoff of the solves, whose pattern depends on the machine's BLAS kernels (on
// another processor the old detector saw none): that the old detector fails on roundoff is
// asserted with fixed inputs by NoInflectionInsideAnExactlyLinearSegment; here only the answer.
TEST(CriticalForce, LinearPathOfTheCapHasNone) {
  IndentationSetup s(cap_125("linear", 10.0), 1);
  const PathResult r = run_indentation_path(s);
  ASSERT_TRUE(r.completed) << r.reason;
  EXPECT_EQ(inflections(r), 0) << "the old detector "
                               << (old_detector_reports(r.points, 2) ? "reports"
                                                                     : "does not report")
                               << " one on this machine";
}

// The nonlinear path to 2 mm (pseudo-arclength, the library's curve-feature detector): the old
// detector reported k11 inflections at 0.45 and 1.29 mm on its points; none is resolved. Both
// with the first step from the tangent at first touch (no onset watch: the points on which the
// old detector reports) and from the linear twin's state (the default; other points).
TEST(CriticalForce, NonlinearPathOfTheCapHasNoneBelow2mm) {
  IndentationSetup plain(cap_125("nonlinear", 2.0), 1);
  PathControl control;
  control.critical_points = false;
  const PathResult r = run_indentation_path(plain, {}, control);
  ASSERT_TRUE(r.completed) << r.reason;
  EXPECT_TRUE(old_detector_reports(r.points, 0));
  EXPECT_EQ(inflections(r), 0);
  IndentationSetup s(cap_125("nonlinear", 2.0), 1);
  const PathResult d = run_indentation_path(s);
  ASSERT_TRUE(d.completed) << d.reason;
  EXPECT_EQ(inflections(d), 0);
}

}  // namespace
}  // namespace si
