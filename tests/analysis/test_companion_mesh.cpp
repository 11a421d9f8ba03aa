// The force's error from a companion run (analysis/companion_mesh.hpp): the companion's case, and
// Richardson's arithmetic against forces whose error is exactly of order 2 in the element size,
// F_h = F* (1 - c h^2), for which |F_h - F_2h| / 3 is the true error to round-off. What it must not
// report: an estimate where the companion has no point at the depth, at zero force, or on a
// switched branch.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/companion_mesh.hpp"

namespace si {
namespace {

PathPoint point(double depth, double force, int branch = 0) {
  PathPoint p;
  p.state.depth = depth;
  p.state.force = force;
  p.branch = branch;
  return p;
}

double exact_force(double depth) {
  return 1000 * std::pow(depth, 1.5) + 200 * depth;
}

// The forces of a mesh of size h whose error is c h^2 of the force.
PathResult path_on_mesh(double h, const std::vector<double>& depths) {
  PathResult r;
  for (double d : depths) r.points.push_back(point(d, exact_force(d) * (1 - 0.3 * h * h)));
  return r;
}

TEST(CompanionMesh, CaseDoublesTheSizesAndLandsOnTheRunsDepths) {
  IndentationCase c;
  c.mesh.size_apex = 0.4;
  c.mesh.size_edge = 1.5;
  c.mesh.refine_radius = 9;
  c.mesh.error_estimate = ErrorEstimate::kCompanion;
  c.mesh.tolerance = 0.01;
  c.path.depth_max = 3;
  c.path.stability = true;
  c.path.branch_switch = BranchSwitchSpec{};
  c.damage = DamageSpec{};
  PathResult r;
  // Unsorted, a repeat (a fold), depth 0 and a switched branch's point: none of them is a depth.
  for (const PathPoint& p : {point(0, 0), point(0.5, 10), point(1.25, 30), point(0.9, 20),
                             point(1.25, 28), point(2, 50, 1)})
    r.points.push_back(p);
  const IndentationCase twin = companion_case(c, r);
  EXPECT_DOUBLE_EQ(twin.mesh.size_apex, 0.8);
  EXPECT_DOUBLE_EQ(twin.mesh.size_edge, 3.0);
  EXPECT_EQ(twin.mesh.refine_radius, 9.0);
  EXPECT_EQ(twin.mesh.error_estimate, ErrorEstimate::kRecovery);  // no companion of its own
  EXPECT_EQ(twin.mesh.tolerance, 0);
  EXPECT_EQ(twin.path.depths, (std::vector<double>{0.5, 0.9, 1.25}));
  EXPECT_DOUBLE_EQ(twin.path.depth_max, 1.25);
  EXPECT_FALSE(twin.path.stability);
  EXPECT_FALSE(twin.path.branch_switch);
  EXPECT_FALSE(twin.damage);
}

TEST(CompanionMesh, RichardsonIsExactForAnErrorOfOrderTwo) {
  const std::vector<double> depths{0.1, 0.25, 0.5, 1.0, 2.0};
  for (double h : {0.25, 0.5, 1.0}) {
    PathResult run = path_on_mesh(h, depths);
    attach_force_errors(run, path_on_mesh(2 * h, depths));
    EXPECT_TRUE(run.companion_mesh);
    for (const PathPoint& p : run.points) {
      const double truth = std::abs(exact_force(p.state.depth) - p.state.force) / p.state.force;
      EXPECT_NEAR(p.force_error, truth, 1e-13) << "h " << h << ", depth " << p.state.depth;
    }
  }
  // An error of order 1 is underestimated by the assumed order: (2 - 1) / (4 - 1) of it.
  PathResult run, twin;
  for (double d : depths) {
    run.points.push_back(point(d, exact_force(d) * (1 - 0.1)));
    twin.points.push_back(point(d, exact_force(d) * (1 - 0.2)));
  }
  attach_force_errors(run, twin);
  EXPECT_NEAR(run.points[2].force_error, (0.1 / 0.9) / 3, 1e-14);
}

TEST(CompanionMesh, NoEstimateWithoutATwinPoint) {
  PathResult run, twin;
  for (const PathPoint& p : {point(0, 0), point(0.5, 10), point(1, 20), point(1.5, 30, 1)})
    run.points.push_back(p);
  // The companion stopped before depth 1; it has depth 0.5 to round-off only.
  twin.points = {point(0, 0), point(0.5 + 1e-12, 13)};
  attach_force_errors(run, twin);
  EXPECT_TRUE(std::isnan(run.points[0].force_error));  // zero force
  EXPECT_NEAR(run.points[1].force_error, 0.1, 1e-14);  // |10 - 13| / (3 * 10)
  EXPECT_TRUE(std::isnan(run.points[2].force_error));  // beyond the companion
  EXPECT_TRUE(std::isnan(run.points[3].force_error));  // a switched branch
  EXPECT_EQ(largest_force_error(run), &run.points[1]);
  PathResult none;
  none.points = {point(0, 0)};
  EXPECT_EQ(largest_force_error(none), nullptr);
}

// A run that never left depth 0 (it failed at the start) has no depths for a companion: said, and
// nothing is built or run.
TEST(CompanionMesh, NoCompanionForARunWithoutAPositiveDepth) {
  PathResult run;
  run.points = {point(0, 0)};
  const CompanionRun c = run_companion(IndentationCase{}, run, 1);
  EXPECT_EQ(c.why_not, "the run has no point at a positive depth");
  EXPECT_TRUE(c.path.points.empty());
  EXPECT_FALSE(run.companion_mesh);
}

}  // namespace
}  // namespace si
