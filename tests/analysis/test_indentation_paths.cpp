// Issue 5: natural and pseudo-arclength continuation agree on a monotone path (the cap,
// [0/90]2S, 0-2 mm): the natural run is asked for the depths the arclength run landed on, and
// both must give the same solution there, to the corrector tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "../indentation/indentation_test_support.hpp"
#include "analysis/indentation_run.hpp"
#include "io/csv_table.hpp"
#include "io/path_results.hpp"

namespace si {
namespace {

CaseFile path_case(PathMethod method) {
  return testing::coarse_cap_path_case("[0/90]2S", method, 2.0, 0.2, 0.5);
}

// Natural continuation of case c asked for the depths of run a's points.
PathResult natural_at_depths_of(CaseFile c, const PathResult& a) {
  c.path.method = PathMethod::kNatural;
  c.path.depths.clear();
  for (std::size_t i = 1; i < a.points.size(); ++i)
    c.path.depths.push_back(a.points[i].state.depth);
  IndentationSetup natural(c, 1);
  return run_indentation_path(natural);
}

TEST(IndentationPaths, NaturalAndPseudoArclengthAgreeOnTheCap_0_90_2S) {
  IndentationSetup arclength(path_case(PathMethod::kPseudoArclength), 1);
  const PathResult a = run_indentation_path(arclength);
  ASSERT_TRUE(a.completed) << a.reason;
  ASSERT_GT(a.points.size(), 4u);

  const PathResult b = natural_at_depths_of(path_case(PathMethod::kNatural), a);
  ASSERT_TRUE(b.completed) << b.reason;

  // Compare at the arclength run's depths (the natural run may add substeps).
  std::size_t j = 0;
  for (const PathPoint& p : a.points) {
    while (j < b.points.size() && b.points[j].state.depth < p.state.depth - 1e-12) ++j;
    ASSERT_LT(j, b.points.size());
    const IndentationState& x = p.state;
    const IndentationState& y = b.points[j].state;
    ASSERT_NEAR(x.depth, y.depth, 1e-12);
    // Corrector tolerance 1e-10 of the force scale kappa * step: 1e-8 relative is safe.
    EXPECT_NEAR(x.force, y.force, 1e-8 * (1 + x.force)) << x.depth;
    EXPECT_NEAR(x.apex_curvature[0], y.apex_curvature[0],
                1e-8 * (1e-3 + std::abs(x.apex_curvature[0])));
    EXPECT_NEAR(x.energy, y.energy, 1e-8 * (1 + x.energy)) << x.depth;
  }
  EXPECT_GT(a.points.back().state.force, 0.0);
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// contact.solver active_set (the primal-dual active-set method on the depth grid, from the
// undeformed start) against the KINSOL natural path of the same case, at every grid depth.
TEST(IndentationPaths, ActiveSetGridAgreesWithKinsol) {
  CaseFile c = testing::coarse_cap_path_case("[0/0]2S", PathMethod::kNatural, 0.6, 0.2, 0.2);
  IndentationSetup kinsol(c, 1);
  const PathResult a = run_indentation_path(kinsol);
  c.contact.solver = ContactSolver::kActiveSet;
  IndentationSetup active_set(c, 1);
  const PathResult b = run_indentation_path(active_set);
  ASSERT_TRUE(b.completed) << b.reason;
  EXPECT_EQ(b.method, RunMethod::kActiveSet);
  for (const PathPoint& q : b.points) {
    for (const PathPoint& p : a.points) {
      if (std::abs(p.state.depth - q.state.depth) < 1e-12) {
        EXPECT_NEAR(p.state.force, q.state.force, 1e-8 * (1 + p.state.force)) << p.state.depth;
      }
    }
  }
  EXPECT_EQ(b.points.size(), 4u);  // 0, 0.2, 0.4, 0.6
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// Issue 7: a local law in series (yang_sun) on the nonlinear cap path. The pseudo-arclength run
// starts at h = 0 (alpha = 0, where dF/dalpha = 0) and reaches 1 mm; the active-set grid of the
// same case gives the same force at every grid depth (to the corrector tolerance, 1e-8), and at
// every point the travel splits into the apex face deflection plus the local approach (the apex
// is in contact; on the axis its director does not turn): h = apex_w + alpha to 1e-8 mm; the
// force is k alpha^1.5. The local law makes the path softer than `none` at every depth.
TEST(IndentationPaths, YangSunLocalLaw_ArclengthAndActiveSetAgreeAndTravelSplits) {
  CaseFile c =
      testing::coarse_cap_path_case("[0/0]2S", PathMethod::kPseudoArclength, 1.0, 0.2, 0.5);
  c.contact.local = LocalContactModel::kYangSun;
  IndentationSetup arclength(c, 1);
  const PathResult a = run_indentation_path(arclength);
  ASSERT_TRUE(a.completed) << a.reason;
  const LocalContactLaw& law = arclength.problem->local_law();
  for (const PathPoint& p : a.points) {
    const IndentationState& s = p.state;
    EXPECT_NEAR(s.apex_deflection + s.local_indentation, s.depth, 1e-8) << s.depth;
    EXPECT_NEAR(s.force, law.force(s.local_indentation), 1e-8 * (1 + s.force)) << s.depth;
  }
  c.path.method = PathMethod::kNatural;
  c.path.depths.clear();
  for (std::size_t i = 1; i < a.points.size(); ++i)
    c.path.depths.push_back(a.points[i].state.depth);
  c.contact.solver = ContactSolver::kActiveSet;
  IndentationSetup active_set(c, 1);
  const PathResult b = run_indentation_path(active_set);
  ASSERT_TRUE(b.completed) << b.reason;
  ASSERT_EQ(b.points.size(), a.points.size());
  c.contact.local = LocalContactModel::kNone;
  IndentationSetup none(c, 1);
  const PathResult n = run_indentation_path(none);
  ASSERT_TRUE(n.completed) << n.reason;
  for (std::size_t i = 1; i < a.points.size(); ++i) {
    const IndentationState& x = a.points[i].state;
    EXPECT_NEAR(x.force, b.points[i].state.force, 1e-8 * (1 + x.force)) << x.depth;
    EXPECT_LT(x.force, n.points[i].state.force) << x.depth;
    std::cout << "  h = " << x.depth << " mm: F = " << x.force << " N (none "
              << n.points[i].state.force << " N), apex w = " << x.apex_deflection
              << " mm, alpha = " << x.local_indentation << " mm\n";
  }
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// A thin deep cap (aluminium 2024-T3, t = 0.5 mm, R = 40 mm over a 25 mm base radius: rise
// 8.8 mm), clamped, pressed by a 5 mm sphere to 16 mm: the apex region inverts and the force
// passes a maximum (measured 3.68 kN at 14.06 mm on this quarter model) and falls. Issue 5: the
// pseudo-arclength path runs past it to the end, the maximum located as an event; every point is
// an equilibrium (KKT conditions, contact force = support reactions); and the natural path,
// asked for the same depths, gives the same solutions on the falling branch.
CaseFile snapping_cap(PathMethod method) {
  CaseFile c = parse_case_file(
      "material: aluminium-2024-t3\n"
      "laminate: {layup: \"[0]\", ply_thickness: 0.5 mm}\n"
      "shell: {type: spherical_cap, base_radius: 25 mm, radius: 40 mm, edge: clamped}\n"
      "mesh: {element: mitc4, size_apex: 2 mm, size_edge: 3 mm, refine_radius: 13 mm,"
      " symmetry: quarter}\n"
      "kinematics: nonlinear\n"
      "indenter: {shape: sphere, radius: 5 mm}\n"
      "path: {method: pseudo_arclength, depth_max: 16 mm, step: 0.1 mm}\n",
      "snapping_cap.yaml");
  c.path.method = method;
  return c;
}

TEST(IndentationPaths, ThinDeepCapPastItsForceMaximum_PseudoArclengthAndNaturalAgree) {
  IndentationSetup arclength(snapping_cap(PathMethod::kPseudoArclength), 1);
  const PathResult a = run_indentation_path(arclength);
  ASSERT_TRUE(a.completed) << a.reason;
  const cont::Event* maximum = nullptr;
  for (const cont::Event& e : a.events)
    if (e.type == cont::EventType::kMonitorMax && e.monitor == "force_N") maximum = &e;
  ASSERT_NE(maximum, nullptr);
  EXPECT_TRUE(maximum->located);
  double peak = 0;
  for (const PathPoint& p : a.points) peak = std::max(peak, p.state.force);
  EXPECT_LT(a.points.back().state.force, 0.9 * peak);  // it fell past the maximum
  const double kappa = arclength.problem->stiffness_scale();
  for (const PathPoint& p : a.points) {
    const IndentationState& s = p.state;
    const double scale = std::max(s.force, kappa * 0.1);  // force_scale: T_N or kappa x 0.1 mm
    EXPECT_GT(s.min_multiplier, -1e-8 * scale) << s.depth;
    EXPECT_GT(kappa * s.min_gap, -1e-8 * scale) << s.depth;
    EXPECT_NEAR(s.force, s.reaction, 1e-9 * scale) << s.depth;
  }

  const PathResult b = natural_at_depths_of(snapping_cap(PathMethod::kNatural), a);
  ASSERT_TRUE(b.completed) << b.reason;
  std::size_t j = 0, compared_past_peak = 0;
  for (const PathPoint& p : a.points) {
    while (j < b.points.size() && b.points[j].state.depth < p.state.depth - 1e-12) ++j;
    ASSERT_LT(j, b.points.size());
    EXPECT_NEAR(p.state.force, b.points[j].state.force, 1e-8 * (1 + p.state.force))
        << p.state.depth;
    compared_past_peak += p.state.depth > maximum->p;
  }
  EXPECT_GE(compared_past_peak, 2u);
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// path_grid.csv against a different method: the pseudo-arclength run's grid (Hermite on the
// branch between points up to 1 mm apart, io/path_results.hpp) against natural continuation
// solved at every grid depth, on the coarse quarter cap 0-4 mm. On this 2 mm mesh each new ring
// of contact nodes puts a kink into T(h) that no cubic between two points follows. A segment
// whose two points have the same contact set has none: there the grid is cubic (measured at
// most 1.9e-5 in force). Across a kink it errs by up to 5.0e-3 in force and 2.8e-3 in energy
// (measured; how many segments hold a kink, and how far into them, depends on where the
// corrector puts the points); linear interpolation of the same points errs by 1.9e-2.
TEST(IndentationPaths, DepthGridOfAnArclengthRunMatchesSolvesAtTheGridDepths) {
  const CaseFile c =
      testing::coarse_cap_path_case("[0/0]2S", PathMethod::kPseudoArclength, 4.0, 0.1, 1.0);
  IndentationSetup arclength(c, 1);
  const PathResult a = run_indentation_path(arclength);
  ASSERT_TRUE(a.completed) << a.reason;
  CaseFile nc = c;
  nc.path.method = PathMethod::kNatural;
  IndentationSetup natural(nc, 1);
  const PathResult b = run_indentation_path(natural);
  ASSERT_TRUE(b.completed) << b.reason;

  const std::string file = ::testing::TempDir() + "shellindent_depth_grid.csv";
  std::ofstream(file) << path_grid_csv(a, c.path.step, c.path.depth_max);
  const CsvTable grid = read_csv_table(file);
  std::remove(file.c_str());
  const std::vector<double> depth = grid.numeric_column("depth_mm");
  const std::vector<double> force = grid.numeric_column("force_N");
  const std::vector<double> energy = grid.numeric_column("energy_Nmm");
  double worst_force = 0, worst_energy = 0, worst_linear = 0, worst_smooth = 0;
  int smooth = 0;
  for (const PathPoint& p : b.points) {
    if (p.state.depth < 0.5) continue;  // first contacts: kinks a grid step apart
    std::size_t k = 0;
    while (k < depth.size() && std::abs(depth[k] - p.state.depth) > 1e-9) ++k;
    ASSERT_LT(k, depth.size()) << p.state.depth;
    const double error = std::abs(force[k] / p.state.force - 1);
    worst_force = std::max(worst_force, error);
    worst_energy = std::max(worst_energy, std::abs(energy[k] / p.state.energy - 1));
    for (std::size_t i = 0; i + 1 < a.points.size(); ++i) {
      const IndentationState &s0 = a.points[i].state, &s1 = a.points[i + 1].state;
      if (p.state.depth <= s0.depth || p.state.depth >= s1.depth) continue;
      const double t = (p.state.depth - s0.depth) / (s1.depth - s0.depth);
      const double linear = (1 - t) * s0.force + t * s1.force;
      worst_linear = std::max(worst_linear, std::abs(linear / p.state.force - 1));
      if (s0.contact_nodes == s1.contact_nodes && p.state.contact_nodes == s0.contact_nodes) {
        worst_smooth = std::max(worst_smooth, error);
        ++smooth;
      }
    }
  }
  std::cout << "  grid vs solves beyond 0.5 mm: force " << worst_force << ", energy "
            << worst_energy << "; on " << smooth << " depths without a kink " << worst_smooth
            << " (linear interpolation of the points: force " << worst_linear << ")\n";
  EXPECT_LT(worst_force, 1e-2);
  EXPECT_LT(worst_energy, 1e-2);
  EXPECT_LT(worst_force, 0.5 * worst_linear);
  EXPECT_GE(smooth, 5);
  EXPECT_LT(worst_smooth, 1e-4);  // cubic accuracy where T(h) is smooth
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// Landing (continuation/arclength_stepper.hpp): the pseudo-arclength run's last point is on
// depth_max exactly and the explicitly requested depths are points of the branch, so their rows
// of path_grid.csv are converged points, not interpolated; at those depths the run agrees with
// natural continuation to the corrector tolerance.
TEST(IndentationPaths, ArclengthLandsOnDepthMaxAndRequestedDepths) {
  CaseFile c =
      testing::coarse_cap_path_case("[0/0]2S", PathMethod::kPseudoArclength, 1.8, 0.1, 0.5);
  c.path.depths = {0.45, 1.3};
  IndentationSetup arclength(c, 1);
  const PathResult a = run_indentation_path(arclength);
  ASSERT_TRUE(a.completed) << a.reason;
  EXPECT_EQ(a.points.back().state.depth, 1.8);
  for (double h : c.path.depths)
    EXPECT_TRUE(std::any_of(a.points.begin(), a.points.end(), [h](const PathPoint& p) {
      return p.state.depth == h;
    })) << h;

  const std::string file = ::testing::TempDir() + "shellindent_landing_grid.csv";
  std::ofstream(file) << path_grid_csv(a, c.path.step, c.path.depth_max);
  const CsvTable grid = read_csv_table(file);
  std::remove(file.c_str());
  const std::vector<double> depth = grid.numeric_column("depth_mm");
  const std::vector<double> interpolated = grid.numeric_column("interpolated");
  ASSERT_FALSE(depth.empty());
  EXPECT_NEAR(depth.back(), 1.8, 1e-12);
  EXPECT_EQ(interpolated.back(), 0.0);  // the last row is the last point
  for (std::size_t k = 0; k < depth.size(); ++k)
    if (std::abs(depth[k] - 1.3) < 1e-9) {
      EXPECT_EQ(interpolated[k], 0.0);
    }

  CaseFile nc = c;
  nc.path.method = PathMethod::kNatural;
  nc.path.depths = {0.45, 1.3, 1.8};
  IndentationSetup natural(nc, 1);
  const PathResult b = run_indentation_path(natural);
  ASSERT_TRUE(b.completed) << b.reason;
  for (double h : nc.path.depths) {
    const auto at = [h](const PathResult& r) {
      return std::find_if(r.points.begin(), r.points.end(),
                          [h](const PathPoint& p) { return p.state.depth == h; });
    };
    ASSERT_NE(at(a), a.points.end());
    ASSERT_NE(at(b), b.points.end());
    const double fa = at(a)->state.force, fb = at(b)->state.force;
    EXPECT_NEAR(fa, fb, 1e-8 * (1 + fb)) << h;
  }
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// path.target_iterations: the step controller scales the next step by target / iterations
// (clamped to [1/2, 2]), so a higher target grows steps the default holds (4 iterations) and
// the path needs fewer points; the points it lands on are the same solutions.
TEST(IndentationPaths, TargetIterationsGrowsTheStepAndKeepsTheSolution) {
  CaseFile c =
      testing::coarse_cap_path_case("[0/0]2S", PathMethod::kPseudoArclength, 3.0, 0.1, 1.0);
  IndentationSetup base_setup(c, 1);
  const PathResult base = run_indentation_path(base_setup);
  ASSERT_TRUE(base.completed) << base.reason;
  // The comparison means something only if the default held a step at 4 or 5 iterations.
  ASSERT_TRUE(std::any_of(base.points.begin() + 1, base.points.end() - 1, [](const PathPoint& p) {
    return p.iterations == 4 || p.iterations == 5;
  }));

  c.path.target_iterations = 6;
  IndentationSetup eager_setup(c, 1);
  const PathResult eager = run_indentation_path(eager_setup);
  ASSERT_TRUE(eager.completed) << eager.reason;
  EXPECT_LT(eager.points.size(), base.points.size());
  // Both land on depth_max exactly; corrector tolerance 1e-10 of the force scale.
  ASSERT_EQ(base.points.back().state.depth, 3.0);
  ASSERT_EQ(eager.points.back().state.depth, 3.0);
  EXPECT_NEAR(eager.points.back().state.force, base.points.back().state.force,
              1e-8 * base.points.back().state.force);
}

}  // namespace
}  // namespace si
