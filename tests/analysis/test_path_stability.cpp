// path.stability on the runs (indentation_run.cpp): what the points and events carry, with and
// without it. What must not be reported: the paper's cap (coarse quarter model) is stable along
// its fundamental path (every eigenvalue of the restricted tangent positive, checked at each
// point against the problem's own analysis), so a stability_change there would be a false alarm.
#include <gtest/gtest.h>

#include <cmath>

#include "../indentation/indentation_test_support.hpp"
#include "analysis/indentation_run.hpp"
#include "analysis/path_columns.hpp"

namespace si {
namespace {

using testing::coarse_cap_path_case;

int stability_events(const PathResult& r) {
  int n = 0;
  for (const cont::Event& e : r.events) n += e.type == cont::EventType::kStabilityChange;
  return n;
}

TEST(PathStability, PaperCapFundamentalPathIsStable_NoStabilityEvent) {
  CaseFile c = coarse_cap_path_case("[0/90]2S", PathMethod::kPseudoArclength, 3.0, 0.25, 0.5);
  c.path.stability = true;
  IndentationSetup s(c, 1);
  const PathResult r = run_indentation_path(s);
  ASSERT_TRUE(r.completed) << r.reason;
  EXPECT_TRUE(r.stability);
  ASSERT_GT(r.points.size(), 6u);
  for (const PathPoint& p : r.points) {
    EXPECT_EQ(p.negative_eigenvalues, 0) << p.state.depth;
    EXPECT_TRUE(p.stable) << p.state.depth;
    EXPECT_GT(p.lowest_eigenvalue, 0.0) << p.state.depth;
  }
  EXPECT_EQ(stability_events(r), 0);
  // The written columns include the stability ones (and the branch), restored from their values.
  const std::vector<PathColumn> columns = result_columns(r);
  EXPECT_EQ(columns.size(), base_columns().size() + 3);  // stable, lowest_eigenvalue, branch
  const std::vector<double> v = path_point_values(r.points.back(), columns);
  const PathPoint back = path_point_from_values(v, columns);
  EXPECT_TRUE(back.stable);
  EXPECT_EQ(back.lowest_eigenvalue, r.points.back().lowest_eigenvalue);
  EXPECT_EQ(back.branch, 0);
}

// Without the key nothing is computed and the stability columns are not written.
TEST(PathStability, OffByDefault_NothingComputedNoColumns) {
  CaseFile c = coarse_cap_path_case("[0/90]2S", PathMethod::kPseudoArclength, 0.5, 0.25, 0.5);
  IndentationSetup s(c, 1);
  const PathResult r = run_indentation_path(s);
  ASSERT_TRUE(r.completed) << r.reason;
  EXPECT_FALSE(r.stability);
  for (const PathPoint& p : r.points) {
    EXPECT_EQ(p.negative_eigenvalues, -1);
    EXPECT_TRUE(std::isnan(p.lowest_eigenvalue));
  }
  EXPECT_EQ(result_columns(r), base_columns());
  for (PathColumn col : result_columns(r))
    EXPECT_FALSE(path_column(col).stability) << column_name(col);
}

// The analysis evaluates the gaps again, whose Newton guesses steer the next solve at round-off
// level: they are kept (IndentationProblem::stability_matrices), so the path with stability is
// the path without it, bit for bit (every column but the stability ones, and every event).
TEST(PathStability, PathIdenticalWithAndWithout_BitForBit) {
  for (PathMethod method : {PathMethod::kPseudoArclength, PathMethod::kNatural}) {
    CaseFile c = coarse_cap_path_case("[0/0]2S", method, 3.0, 0.25, 0.5);
    IndentationSetup plain(c, 1);
    c.path.stability = true;
    IndentationSetup analysed(c, 1);
    const PathResult a = run_indentation_path(plain);
    const PathResult b = run_indentation_path(analysed);
    ASSERT_TRUE(a.completed && b.completed) << a.reason << b.reason;
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      const std::vector<double> va = path_point_values(a.points[i], base_columns());
      const std::vector<double> vb = path_point_values(b.points[i], base_columns());
      for (std::size_t k = 0; k < va.size(); ++k) {
        if (std::isnan(va[k]) && std::isnan(vb[k])) continue;
        EXPECT_EQ(va[k], vb[k]) << column_name(base_columns()[k]) << " at point " << i;
      }
    }
    ASSERT_EQ(a.events.size(), b.events.size() - static_cast<std::size_t>(stability_events(b)));
    for (std::size_t i = 0, j = 0; j < b.events.size(); ++j) {
      if (b.events[j].type == cont::EventType::kStabilityChange) continue;
      EXPECT_EQ(a.events[i].p, b.events[j].p) << a.events[i].name;
      EXPECT_EQ(a.events[i].type, b.events[j].type);
      ++i;
    }
  }
}

// The depth grids analyse each point themselves: the linear path (K positive definite on any
// contact set) is stable at every depth, its lowest eigenvalue the problem's own at that point.
TEST(PathStability, LinearGridPointsAnalysed) {
  CaseFile c = testing::coarse_cap_case("linear", "[0/90]2S", "quarter");
  c.path.depth_max = 2.0;
  c.path.step = 0.5;
  c.path.stability = true;
  IndentationSetup s(c, 1);
  const PathResult r = run_indentation_path(s);
  ASSERT_TRUE(r.completed) << r.reason;
  ASSERT_EQ(r.points.size(), 5u);
  for (const PathPoint& p : r.points) {
    EXPECT_EQ(p.negative_eigenvalues, 0);
    EXPECT_GT(p.lowest_eigenvalue, 0.0);
  }
  EXPECT_EQ(stability_events(r), 0);
  cont::Stability direct;
  ASSERT_TRUE(s.problem->stability(r.final_unknowns, 2.0, 1, direct));
  EXPECT_NEAR(r.points.back().lowest_eigenvalue, direct.eigenvalues[0],
              1e-10 * direct.eigenvalues[0]);
}

}  // namespace
}  // namespace si
