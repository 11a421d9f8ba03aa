// path.stability on the runs (indentation_run.cpp): what the points and events carry, with and
// without it. What must not be reported: the paper's cap (coarse quarter model) is stable along
// its fundamental path (every eigenvalue of the restricted tangent positive, checked at each
// point against the problem's own analysis), so a stability_change there would be a false alarm.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "../indentation/indentation_test_support.hpp"
#include "analysis/indentation_run.hpp"
#include "analysis/path_columns.hpp"
#include "continuation/stability_analysis.hpp"

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
    EXPECT_EQ(path_column(col).group, ColumnGroup::kEveryRun) << column_name(col);
}

// The analysis evaluates the gaps again, whose Newton guesses steer the next solve at round-off
// level: they are kept (IndentationProblem::stability_matrices). It also makes the Krylov
// solver's preconditioner anew at each point (penalized_stability), which changes the GMRES
// iterates at the level of its tolerance (1e-12) only. So the path with stability is the path
// without it to round-off: every column but the stability ones to 1e-9 of its own largest value
// (the KKT residuals of the depth's and force's), and every event at the same depth to 1e-9 mm.
TEST(PathStability, PathWithAndWithout_SameToRoundOff) {
  for (PathMethod method : {PathMethod::kPseudoArclength, PathMethod::kNatural}) {
    CaseFile c = coarse_cap_path_case("[0/0]2S", method, 3.0, 0.25, 0.5);
    IndentationSetup plain(c, 1);
    c.path.stability = true;
    IndentationSetup analysed(c, 1);
    const PathResult a = run_indentation_path(plain);
    const PathResult b = run_indentation_path(analysed);
    ASSERT_TRUE(a.completed && b.completed) << a.reason << b.reason;
    EXPECT_GT(analysed.problem->counters().stability_from_preconditioner, 0);
    ASSERT_EQ(a.points.size(), b.points.size());
    const std::vector<PathColumn> columns = base_columns();
    std::vector<double> scale(columns.size(), 0.0);
    for (const PathPoint& p : a.points) {
      const std::vector<double> v = path_point_values(p, columns);
      for (std::size_t k = 0; k < v.size(); ++k)
        if (std::isfinite(v[k])) scale[k] = std::max(scale[k], std::abs(v[k]));
    }
    // The KKT residuals are round-off themselves: their scale is the depth's, the force's or
    // their product's, not their own.
    const auto column_scale = [&](std::size_t k) {
      const double depth = scale[0], force = scale[1];  // kDepth, kForce
      switch (columns[k]) {
        case PathColumn::kMinGap:
          return depth;
        case PathColumn::kMinMultiplier:
          return force;
        case PathColumn::kMaxComplementarity:
          return depth * force;
        default:
          return scale[k];
      }
    };
    ASSERT_EQ(columns[0], PathColumn::kDepth);
    ASSERT_EQ(columns[1], PathColumn::kForce);
    double worst = 0;
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      const std::vector<double> va = path_point_values(a.points[i], columns);
      const std::vector<double> vb = path_point_values(b.points[i], columns);
      for (std::size_t k = 0; k < va.size(); ++k) {
        if (std::isnan(va[k]) && std::isnan(vb[k])) continue;
        const double allowed = 1e-9 * column_scale(k);
        EXPECT_LE(std::abs(va[k] - vb[k]), allowed) << column_name(columns[k]) << " at point " << i;
        if (column_scale(k) > 0) worst = std::max(worst, std::abs(va[k] - vb[k]) / column_scale(k));
      }
    }
    std::printf("[ stability] largest difference with and without: %.2g of the column\n", worst);
    ASSERT_EQ(a.events.size(), b.events.size() - static_cast<std::size_t>(stability_events(b)));
    for (std::size_t i = 0, j = 0; j < b.events.size(); ++j) {
      if (b.events[j].type == cont::EventType::kStabilityChange) continue;
      EXPECT_NEAR(a.events[i].p, b.events[j].p, 1e-9) << a.events[i].name;
      EXPECT_EQ(a.events[i].type, b.events[j].type);
      ++i;
    }
  }
}

// The two routes of the analysis agree: at a converged point of the cap's path, factored there as
// the continuation does, stability() takes the preconditioner's factor (the counter says so) and
// gives the same count and lowest eigenvalues as the direct analysis of Z'HZ to 1e-8 relative (the
// penalty's bound, continuation/penalized_stability.hpp), never above them, and the same mode
// to its sign.
TEST(PathStability, PreconditionerRouteMatchesTheDirectAnalysis) {
  CaseFile c = coarse_cap_path_case("[0/90]2S", PathMethod::kPseudoArclength, 2.0, 0.25, 0.5);
  IndentationSetup s(c, 1);
  const PathResult r = run_indentation_path(s);
  ASSERT_TRUE(r.completed) << r.reason;
  IndentationProblem& problem = *s.problem;
  const cont::Vector& z = r.final_unknowns;
  const double h = r.points.back().state.depth;
  ASSERT_TRUE(problem.factorize(z, h));
  const long before = problem.counters().stability_from_preconditioner;
  cont::Stability fast;
  ASSERT_TRUE(problem.stability(z, h, 3, fast));
  EXPECT_EQ(problem.counters().stability_from_preconditioner, before + 1);
  // The direct route: Z'HZ of the same matrices, factored and analysed by itself.
  const IndentationProblem::StabilityMatrices m = problem.stability_matrices(z, h);
  cont::Stability direct;
  ASSERT_TRUE(cont::analyse_stability(m.H, m.A, 3, direct));
  EXPECT_EQ(fast.negative, direct.negative);
  EXPECT_EQ(fast.negative, 0);
  ASSERT_EQ(fast.eigenvalues.size(), 3);
  for (int j = 0; j < 3; ++j) {
    EXPECT_NEAR(fast.eigenvalues(j), direct.eigenvalues(j), 1e-8 * direct.eigenvalues(j)) << j;
    EXPECT_LE(fast.eigenvalues(j), direct.eigenvalues(j) * (1 + 1e-12)) << j;
  }
  // The lowest mode (simple here): the same up to sign in the shell part.
  const int nf = problem.num_shell_unknowns();
  const cont::Vector v = fast.modes[0].head(nf);
  cont::Vector w = direct.modes[0];
  if (v.dot(w) < 0) w = -w;
  EXPECT_LT((v - w).norm(), 1e-6);
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
