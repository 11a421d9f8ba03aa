// Snap-through and snap-back of Sze's hinged cylindrical roof, traced by pseudo-arclength
// continuation (continuation/pseudo_arclength.hpp) of the load-controlled problem
// (analysis/load_problem.hpp) with the mitc4 element: K.Y. Sze, X.H. Liu, S.H. Lo, "Popular
// benchmark problems for geometric nonlinear analysis of shells", Finite Elements in Analysis
// and Design 40 (2004) 1551-1569, section 3.8, isotropic roofs (a) h = 12.7 and (d) h = 6.35
// (problem data: ../shared/benchmarks/nonlinear.md). The reference paths are ABAQUS S4R Riks
// solutions tabulated by Sze et al., copied below from ../shared/benchmarks/csv/
// sze2004_3-8a_hinged_roof_isotropic_h12.7.csv and sze2004_3-8d_hinged_roof_isotropic_h6.35.csv
// (transcribed from MBDyn tests/plates/sze2004/sze38/sze38_ref_{a,d}.dat).
//
// Acceptance (issue 5): the first limit load within 1 % and the path within 2 % at the
// tabulated points, both in units of Pmax = 3000 (the tables' P/Pmax; see path_errors below for
// how a tabulated point is compared).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "../verification_record.hpp"
#include "analysis/load_problem.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "model/cylindrical_panel_mesh.hpp"
#include "model/dof_map.hpp"
#include "nonlinear_benchmark_support.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"
#include "sze_roof_support.hpp"
#include "sze_tables.hpp"

namespace si {
namespace {

using verification::kRoofPmax;
using verification::make_sze_roof;
using verification::sze_roof_settings;
constexpr double kPmax = kRoofPmax;

using PathPoint = verification::RoofTablePoint;
const std::vector<PathPoint>& kSze38a = verification::kSze38aTable;
const std::vector<PathPoint>& kSze38d = verification::kSze38dTable;

// The first local maximum of P/Pmax along a tabulated path (the snap-through load).
double first_limit_load(const std::vector<PathPoint>& path) {
  for (std::size_t i = 1; i + 1 < path.size(); ++i)
    if (path[i].load_factor >= path[i - 1].load_factor &&
        path[i].load_factor > path[i + 1].load_factor)
      return path[i].load_factor;
  return std::numeric_limits<double>::quiet_NaN();
}

// A path cut into pieces on which the deflection is monotonic (cut at its turning points).
std::vector<std::vector<PathPoint>> monotonic_pieces(const std::vector<PathPoint>& path) {
  std::vector<std::vector<PathPoint>> pieces{{path.front()}};
  int direction = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double dw = path[i].deflection - path[i - 1].deflection;
    const int d = dw > 0 ? 1 : (dw < 0 ? -1 : direction);
    if (direction != 0 && d != direction) pieces.push_back({path[i - 1]});
    direction = d;
    pieces.back().push_back(path[i]);
  }
  return pieces;
}

// The load factor of a monotonic piece at deflection w (linear interpolation); NaN outside it.
double load_at(const std::vector<PathPoint>& piece, double w) {
  for (std::size_t i = 1; i < piece.size(); ++i) {
    const double w0 = piece[i - 1].deflection, w1 = piece[i].deflection;
    if ((w - w0) * (w - w1) > 0 || w0 == w1) continue;
    const double t = (w - w0) / (w1 - w0);
    return piece[i - 1].load_factor + t * (piece[i].load_factor - piece[i - 1].load_factor);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// Error at each tabulated point, in units of Pmax: the vertical distance |lambda(W_i) - P_i|
// from the tabulated point (W_i, P_i) to our path at the same deflection, lambda(W) interpolated
// linearly between our branch points on the piece of our path that corresponds to the point's
// piece (both paths cut into pieces of monotonic deflection, matched in order: the snap-back
// has three). Where W_i lies beyond the end of our matching piece (a tabulated point at a
// deflection turning point, reached by our piece within a fraction of a mm less), the piece's
// end point is used, i.e. the error is |lambda(end) - P_i|. A tabulated turning point ends one
// piece and starts the next: it is compared on both. Fails (and returns nothing) if the numbers
// of pieces differ.
struct PointError {
  PathPoint reference;
  double error;
  double load_factor;  // ours, lambda(W_i)
};
std::vector<PointError> path_errors(const std::vector<PathPoint>& reference,
                                    const std::vector<PathPoint>& ours) {
  const auto ref_pieces = monotonic_pieces(reference);
  const auto our_pieces = monotonic_pieces(ours);
  std::vector<PointError> errors;
  if (ref_pieces.size() != our_pieces.size()) {
    ADD_FAILURE() << "the reference path has " << ref_pieces.size()
                  << " pieces of monotonic deflection, ours " << our_pieces.size();
    return errors;
  }
  for (std::size_t k = 0; k < ref_pieces.size(); ++k) {
    const auto& piece = our_pieces[k];
    for (const PathPoint& p : ref_pieces[k]) {
      double lambda = load_at(piece, p.deflection);
      if (std::isnan(lambda)) {
        const PathPoint& a = piece.front();
        const PathPoint& b = piece.back();
        lambda = std::abs(p.deflection - a.deflection) < std::abs(p.deflection - b.deflection)
                     ? a.load_factor
                     : b.load_factor;
      }
      errors.push_back({p, std::abs(lambda - p.load_factor), lambda});
    }
  }
  return errors;
}

// Our path: the branch points and the located deflection turning points (monitor extrema), in
// order of arclength, so that each monotonic piece ends exactly at its turning point.
std::vector<PathPoint> branch_path(const cont::Branch& branch) {
  std::vector<std::pair<double, PathPoint>> points;
  for (const cont::Point& p : branch.points) points.push_back({p.arclength, {p.p, p.monitors[1]}});
  for (const cont::Event& e : branch.events)
    if (e.located && !e.monitor.empty()) points.push_back({e.arclength, {e.p, e.monitors[1]}});
  std::stable_sort(points.begin(), points.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<PathPoint> path;
  for (const auto& p : points) path.push_back(p.second);
  return path;
}

struct RoofRun {
  cont::Branch branch;
  std::vector<PathPoint> path;
  double seconds = 0;
};

// The quarter roof with n x n mitc4 elements, traced from lambda = P/Pmax = 0 up to 1.1 by
// pseudo-arclength continuation (sze_roof_support.hpp).
RoofRun trace_roof(double thickness, int n, bool snap_back) {
  // One assembly thread: ctest runs tests side by side; OpenMP spin-waiting is slow under load.
  const verification::SzeRoof roof = make_sze_roof(thickness, n);
  LoadProblem problem(roof.mesh, roof.supports, *roof.element, roof.law, roof.loads, roof.options);
  RoofRun run;
  const auto start = std::chrono::steady_clock::now();
  run.branch =
      cont::pseudo_arclength(problem, problem.initial_point(), 0.0, sze_roof_settings(snap_back));
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.path = branch_path(run.branch);
  return run;
}

std::vector<cont::Event> events_of(const cont::Branch& branch, cont::EventType type) {
  std::vector<cont::Event> out;
  for (const cont::Event& e : branch.events)
    if (e.type == type) out.push_back(e);
  return out;
}

void print_run(const std::string& title, const RoofRun& run) {
  std::printf("%s: %zu points, %d failed steps, %.2f s\n", title.c_str(), run.branch.points.size(),
              run.branch.failed_steps, run.seconds);
  for (const cont::Event& e : run.branch.events)
    std::printf("  event %-12s P/Pmax %8.4f  -W_C %8.3f (located %d, bracket %.1e)\n",
                e.name.c_str(), e.p, e.monitors[1], e.located, e.accuracy);
}

// The first limit load (the first limit_point event of the parameter) against the table's first
// local maximum of P/Pmax: within 1 % of Pmax.
// Errors of the report (verification_record.hpp) are in units of Pmax, as the acceptance.
constexpr const char* kSzeRoofSource = "Sze, Liu & Lo 2004 sec. 3.8, ABAQUS S4R (csv/sze2004_3-8*)";

void record_in_pmax(const std::string& check, double reference, double ours, double tolerance) {
  test::record_verification({"sze-hinged-roof", check, reference, ours, tolerance, kSzeRoofSource,
                             test::ErrorScale::kCustom, 1.0, "Pmax"});
}

void expect_first_limit_load(const std::string& label, const RoofRun& run,
                             const std::vector<PathPoint>& reference) {
  ASSERT_EQ(run.branch.status, cont::Status::kReachedBound) << run.branch.reason;
  const auto limits = events_of(run.branch, cont::EventType::kLimitPoint);
  ASSERT_FALSE(limits.empty());
  EXPECT_TRUE(limits.front().located);
  const double ref_limit = first_limit_load(reference);
  const double limit = limits.front().p;
  std::printf("  first limit load P/Pmax: reference %.4f, ours %.4f (error %.2f %% of Pmax)\n",
              ref_limit, limit, 100 * (limit - ref_limit));
  EXPECT_NEAR(limit, ref_limit, 0.01);
  record_in_pmax(label + ": first limit load P/Pmax", ref_limit, limit, 0.01);
}

// The path: at every tabulated point the error of path_errors (P/Pmax at the same deflection on
// the matching monotonic piece) is at most 0.02, i.e. 2 % of Pmax.
void expect_path_within_2_percent(const std::string& label, const RoofRun& run,
                                  const std::vector<PathPoint>& reference) {
  const std::vector<PointError> errors = path_errors(reference, run.path);
  double worst = 0;
  for (const PointError& e : errors) worst = std::max(worst, e.error);
  std::printf("  path: largest error %.2f %% of Pmax over %zu comparisons\n", 100 * worst,
              errors.size());
  for (const PointError& e : errors) {
    EXPECT_LE(e.error, 0.02) << "tabulated point P/Pmax " << e.reference.load_factor << ", -W_C "
                             << e.reference.deflection;
    char check[96];
    std::snprintf(check, sizeof check, "%s: path P/Pmax at -W_C = %.3f", label.c_str(),
                  e.reference.deflection);
    record_in_pmax(check, e.reference.load_factor, e.load_factor, 0.02);
  }
}

// Measured (mitc4 quarter n x n; first limit load error, largest path error, both in % of Pmax,
// wall time on the loaded 2-vCPU VM): 8x8 -0.11 %, 1.65 % (1.3 s); 12x12 -0.14 %, 1.09 %;
// 16x16 -0.15 %, 0.69 %. 8x8 meets both criteria.
TEST(SzeHingedRoof, SzeLiuLo2004_Sec38a_IsotropicH12p7_Mitc4Quarter8x8) {
  const RoofRun run = trace_roof(12.7, 8, false);
  print_run("Sze 3.8(a) hinged roof h = 12.7, mitc4 quarter 8x8", run);
  expect_first_limit_load("(a) h = 12.7, quarter 8x8", run, kSze38a);
  expect_path_within_2_percent("(a) h = 12.7, quarter 8x8", run, kSze38a);
}

// Snap-through and snap-back: the first limit load and the two turning points of the centre
// deflection (a maximum, then a minimum), traced and located. Measured first limit load error
// (% of Pmax): 8x8 +0.29 % (1.4 s), 12x12 +0.10 %, 16x16 +0.03 %.
TEST(SzeHingedRoof, SzeLiuLo2004_Sec38d_IsotropicH6p35_FirstLimitLoadAndSnapBack_Mitc4Quarter8x8) {
  const RoofRun run = trace_roof(6.35, 8, true);
  print_run("Sze 3.8(d) hinged roof h = 6.35, mitc4 quarter 8x8", run);
  expect_first_limit_load("(d) h = 6.35, quarter 8x8", run, kSze38d);
  const auto maxima = events_of(run.branch, cont::EventType::kMonitorMax);
  const auto minima = events_of(run.branch, cont::EventType::kMonitorMin);
  ASSERT_EQ(maxima.size(), 1u);
  ASSERT_EQ(minima.size(), 1u);
  EXPECT_TRUE(maxima[0].located && minima[0].located);
  EXPECT_LT(maxima[0].arclength, minima[0].arclength);
}

// The Jacobian that factorize() hands to the continuation is the derivative of residual() in the
// chart (K T + D, shell_chart.hpp) also away from equilibrium and at finite rotations: for a
// solve y = J^-1 b at a deformed, unbalanced state, the central difference of F along y returns b
// to truncation and round-off; and residual_p is -f_ext.
TEST(SzeHingedRoof, LoadProblemJacobianMatchesCentralDifference) {
  const verification::SzeRoof roof = make_sze_roof(6.35, 4);
  const Mesh& mesh = roof.mesh;
  LoadProblem problem(roof.mesh, roof.supports, *roof.element, roof.law, roof.loads, roof.options);
  // A state with rotations of about 0.2 rad and displacements of about 10 mm.
  cont::Vector x(problem.size());
  for (int i = 0; i < x.size(); ++i) x[i] = 0.1 * std::sin(1.0 + 0.7 * i) + 0.1 * std::cos(0.3 * i);
  for (int n = 0; n < mesh.num_nodes(); ++n)
    for (int l = 0; l < 3; ++l) {
      const int eq = problem.dofs().equation(DofMap::dof(n, l));
      if (eq >= 0) x[eq] *= 100;
    }
  const double lambda = 0.3;
  cont::Vector b = cont::Vector::Ones(problem.size());
  ASSERT_TRUE(problem.factorize(x, lambda));
  cont::Vector y = b;
  ASSERT_TRUE(problem.solve(y));
  // Largest chart step 1e-3 (mm or rad). Measured |J y - b|: 4.6e-5 at 1e-2 (truncation,
  // O(eps^2)), 1.5e-6 at 1e-3, 1.7e-5 at 1e-4 (round-off of the membrane forces, O(1/eps)). A
  // Jacobian without the chart transform errs by O(|theta|) = 0.1.
  const double eps = 1e-3 / y.cwiseAbs().maxCoeff();
  cont::Vector Fp, Fm;
  ASSERT_TRUE(problem.residual(x + eps * y, lambda, Fp));
  ASSERT_TRUE(problem.residual(x - eps * y, lambda, Fm));
  const cont::Vector Jy = (Fp - Fm) / (2 * eps);
  EXPECT_LT((Jy - b).cwiseAbs().maxCoeff(), 1e-5) << "largest |J y - b| with |b| = 1";

  cont::Vector dF;
  ASSERT_TRUE(problem.residual_p(x, lambda, dF));
  cont::Vector F0, F1;
  ASSERT_TRUE(problem.residual(x, 0.0, F0));
  ASSERT_TRUE(problem.residual(x, 1.0, F1));
  EXPECT_LT((F1 - F0 - dF).cwiseAbs().maxCoeff(), 1e-9 * kPmax);
  EXPECT_NEAR(dF.sum(), kPmax / 4, 1e-9 * kPmax);  // -f_ext: the quarter load, downwards
}

// The path of case (d) needs a fine mesh on the stiff tail after the snap-back (its last
// tabulated points, -W_C = 36.6 and 38.45, where dP/dW = 0.12 Pmax per mm: 0.1 mm of deflection
// is 1.2 % of Pmax). Largest path error (% of Pmax, always at the last point) measured with the
// mitc4 quarter model: 8x8 4.29 (also 2.3 at the deflection maximum and 3.2 at its minimum),
// 12x12 3.17, 16x16 2.57, 20x20 2.18, 22x22 2.04, 24x24 1.91; our tail is stiffer and converges
// to the reference. 24x24 takes 12-28 s on the loaded 2-vCPU VM: run only with
// SHELLINDENT_LONG_TESTS=1 (nonlinear_benchmark_support.hpp).
TEST(SzeHingedRoof, SzeLiuLo2004_Sec38d_IsotropicH6p35_Path_Mitc4Quarter24x24) {
  if (!verification::long_tests_enabled()) GTEST_SKIP() << "set SHELLINDENT_LONG_TESTS=1";
  const RoofRun run = trace_roof(6.35, 24, true);
  print_run("Sze 3.8(d) hinged roof h = 6.35, mitc4 quarter 24x24", run);
  expect_first_limit_load("(d) h = 6.35, quarter 24x24", run, kSze38d);
  expect_path_within_2_percent("(d) h = 6.35, quarter 24x24", run, kSze38d);
}

}  // namespace
}  // namespace si
