// A clamped shallow spherical cap under uniform external pressure, whole (not a quarter) so that
// the modes that are not axisymmetric exist: the load problem's stability along the
// pseudo-arclength path (analysis/load_problem.hpp, load_stability.cpp) finds the first loss of
// stability, classifies it (limit point or bifurcation) and gives its mode, whose circumferential
// wave number n is read by a Fourier analysis of the mode's normal displacement on a ring.
//
// The reference is Huang's (1964) method - the axisymmetric nonlinear path of shallow-shell
// theory and the singularity of each harmonic's second variation along it - evaluated by
// studies/cap_pressure_reference.py (spectral Ritz, converged to 1e-10 and checked there against
// Bessel and Kelvin-function closed forms): with lambda = 2 [3 (1 - nu^2)]^(1/4) sqrt(H / h) (H
// the rise, h the thickness) and p_cl = 2 E h^2 / (R^2 sqrt(3 (1 - nu^2))), at nu = 1/3,
//   lambda = 3: no critical point below 1.5 p_cl;
//   lambda = 4: the axisymmetric limit point first, p / p_cl = 0.573493 (n = 0);
//   lambda = 8: a bifurcation first, n = 4 at 0.766004 (n = 3 follows at 0.773359, n = 5 at
//   0.812879; the limit point at 1.124878).
// (`studies/cap_pressure_reference.py --lambda 3 4 8 --table`.) Huang's own table (reproduced as
// Table 3 of Teng & Rotter 1989) could not be retrieved for this work; the qualitative picture
// (the snap below lambda of about 5.5, n >= 2 above, n growing with lambda) is his.
// R / h = 400 keeps the cap shallow (H / a = 0.06 at lambda = 4, 0.11 at 8), the element size a
// multiple of sqrt(R h), the length the response scales with at fixed lambda; two meshes and
// Richardson's extrapolation (MITC4, O(e^2)) give the converged critical pressure.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "analysis/load_problem.hpp"
#include "continuation/pseudo_arclength.hpp"
#include "model/spherical_cap_mesh.hpp"
#include "model/supports.hpp"
#include "nonlinear_benchmark_support.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si {
namespace {

constexpr double kE = 2.0e5;  // MPa
constexpr double kNu = 1.0 / 3.0;
constexpr double kThickness = 1.0;  // mm
constexpr double kSphere = 400.0;   // mm, R / h = 400

// sqrt(3 (1 - nu^2)).
double root3() {
  return std::sqrt(3 * (1 - kNu * kNu));
}
double classical_pressure() {
  return 2 * kE * kThickness * kThickness / (kSphere * kSphere * root3());
}
// The base radius of the cap of geometric parameter lambda: rise H = h lambda^2 / (4 root3).
double base_radius(double lambda) {
  const double H = kThickness * lambda * lambda / (4 * root3());
  return std::sqrt(2 * kSphere * H - H * H);
}

struct FirstCriticalPoint {
  bool found = false;
  cont::Criticality criticality = cont::Criticality::kNone;
  double pressure_ratio = 0;  // p / p_cl
  int wave_number = -1;
  double dominance = 0;  // share of the mode's ring energy in harmonic wave_number
  double asymmetry = 0;  // skew part of the chart Hessian dropped, at the last stable point
  double seconds = 0;
  int steps = 0;
};

// The dominant circumferential harmonic of the mode's normal displacement (here along z, the
// cap being shallow) over the nodes of the ring 0.3 a < r < 0.8 a: for each n the discrete
// Fourier coefficients c_n = sum w cos(n theta), s_n = sum w sin(n theta); the share of n is
// (c_n^2 + s_n^2) / sum over n of the same (n = 0 ... 16).
std::pair<int, double> wave_number(const Mesh& mesh, const DofMap& dofs, const cont::Vector& mode,
                                   double a) {
  std::vector<double> w(mesh.nodes.size(), 0.0);
  for (int eq = 0; eq < mode.size(); ++eq) {
    const int dof = dofs.free_dofs()[eq];
    if (dof % kShellNodeDofs == 2) w[dof / kShellNodeDofs] = mode[eq];
  }
  constexpr int kHarmonics = 16;
  std::vector<double> power(kHarmonics + 1, 0.0);
  for (int n = 0; n <= kHarmonics; ++n) {
    double c = 0, s = 0;
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) {
      const double r = std::hypot(mesh.nodes[i].x(), mesh.nodes[i].y());
      if (r < 0.3 * a || r > 0.8 * a) continue;
      const double theta = std::atan2(mesh.nodes[i].y(), mesh.nodes[i].x());
      c += w[i] * std::cos(n * theta);
      s += w[i] * std::sin(n * theta);
    }
    power[n] = c * c + s * s;
  }
  int best = 0;
  double total = 0;
  for (int n = 0; n <= kHarmonics; ++n) {
    total += power[n];
    if (power[n] > power[best]) best = n;
  }
  return {best, total > 0 ? power[best] / total : 0.0};
}

// Pseudo-arclength under the follower pressure p_cl times the load factor, stability of every
// point, stopped at the first stability change.
FirstCriticalPoint first_critical_point(double lambda, double element_factor) {
  const double a = base_radius(lambda);
  const double element_size = element_factor * std::sqrt(kSphere * kThickness);
  SphericalCapMeshSpec spec;
  spec.base_radius = a;
  spec.sphere_radius = kSphere;
  spec.size_apex = spec.size_edge = element_size;
  spec.refine_radius = 0.5 * a;
  const Mesh mesh = spherical_cap_mesh(spec);
  const auto element = make_shell_element(ElementType::kMitc4);
  const ShellLaw law = isotropic_shell_law(kE, kNu, kThickness);
  Loads loads;
  // External: towards the sphere's centre, against the outward directors.
  loads.pressures.push_back({-classical_pressure(), true, {}});
  LoadProblemOptions options;
  options.threads = 1;
  LoadProblem problem(mesh, {{SupportKind::kClamped, "edge", -1, {}}}, *element, law, loads,
                      options);

  cont::Settings s;
  s.method = cont::Method::kPseudoArclength;
  s.newton.relative_tolerance = 1e-9;
  s.newton.residual_scale = problem.force_scale();
  s.step_initial = 0.02;
  s.step_min = 1e-6;
  s.step_max = 0.05;
  s.parameter_weight = 1.0;
  s.p_max = 1.2;
  s.max_steps = 400;
  s.stability_modes = 4;  // a pair of n-modes and the next ones
  s.detect_signature_changes = false;

  FirstCriticalPoint out;
  const auto start = std::chrono::steady_clock::now();
  const cont::Callback stop_at_first = [&](const cont::Point& point, const cont::Branch& branch) {
    if (point.stable) out.asymmetry = problem.stability_matrix(point.x, point.p).asymmetry;
    for (const cont::Event& e : branch.events)
      if (e.type == cont::EventType::kStabilityChange) return false;
    return true;
  };
  const cont::Branch branch =
      cont::pseudo_arclength(problem, problem.initial_point(), 0.0, s, stop_at_first);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out.steps = static_cast<int>(branch.points.size());
  for (const cont::Event& e : branch.events) {
    if (e.type != cont::EventType::kStabilityChange) continue;
    out.found = true;
    out.criticality = e.criticality;
    out.pressure_ratio = e.p;
    const auto [n, share] = wave_number(mesh, problem.dofs(), e.mode, a);
    out.wave_number = n;
    out.dominance = share;
    break;
  }
  std::printf(
      "cap lambda %.2f (a = %.3f mm, %d elements, %d unknowns): %s at p / p_cl = %.5f, n = %d "
      "(%.0f %% of the ring's power), skew part %.1e, %d points, %.1f s\n",
      lambda, a, mesh.num_elements(), problem.size(),
      out.found ? cont::criticality_name(out.criticality).c_str() : "nothing", out.pressure_ratio,
      out.wave_number, 100 * out.dominance, out.asymmetry, out.steps, out.seconds);
  return out;
}

// Richardson's extrapolation of a critical pressure from meshes of element factors e1 > e2
// (MITC4's error O(e^2)).
double extrapolated(double p1, double e1, double p2, double e2) {
  return p2 + (p2 - p1) * e2 * e2 / (e1 * e1 - e2 * e2);
}

// The tolerance on a critical pressure, extrapolated (lambda = 4) or on a fine mesh (lambda = 8,
// below): the extrapolation's own error (at lambda = 4 the meshes 0.3/0.2 and 0.2/0.15 give
// estimates 0.06 % apart) or the fine mesh's (0.07-0.32 %), and the model difference
// between the reference's shallow theory under a pressure normal to the base and the deep
// follower-pressure shell here (measured 0.01-0.1 %): 0.5 %.
constexpr double kConvergedTolerance = 5e-3;

// lambda = 3: nothing is critical below 1.2 p_cl (the reference: nothing below 1.5) - the
// detector must not report a change of stability that is not there.
TEST(CapPressureBifurcation, Lambda3_NoCriticalPointBelowThePathsEnd_Huang1964) {
  const FirstCriticalPoint c = first_critical_point(3.0, 0.3);
  EXPECT_FALSE(c.found);
  EXPECT_GT(c.steps, 5);
}

// lambda = 4: the axisymmetric snap first, at 0.573493 p_cl. Measured: 0.58026 (element factor
// 0.3, 1565 unknowns) and 0.57613 (0.2, 3605), extrapolated 0.57283 (-0.11 %); 10 s in all.
TEST(CapPressureBifurcation, Lambda4_AxisymmetricLimitPointFirst_Huang1964) {
  constexpr double kReference = 0.573493;
  const FirstCriticalPoint coarse = first_critical_point(4.0, 0.3);
  const FirstCriticalPoint fine = first_critical_point(4.0, 0.2);
  for (const FirstCriticalPoint& c : {coarse, fine}) {
    ASSERT_TRUE(c.found);
    EXPECT_EQ(c.criticality, cont::Criticality::kLimitPoint);
    EXPECT_EQ(c.wave_number, 0);
    EXPECT_LT(c.asymmetry, 1e-6);  // the follower pressure with a clamped edge is conservative
  }
  // The error falls with the mesh, and the extrapolation meets the reference.
  EXPECT_LT(std::abs(fine.pressure_ratio - kReference),
            std::abs(coarse.pressure_ratio - kReference));
  const double limit = extrapolated(coarse.pressure_ratio, 0.3, fine.pressure_ratio, 0.2);
  EXPECT_NEAR(limit / kReference, 1.0, kConvergedTolerance);
}

// lambda = 8: a bifurcation into n = 4 before the limit point, at 0.766004 p_cl. n = 3 follows
// 1 % above it (0.773359), within a coarse mesh's error, so the order of the two is resolved only
// on a fine one: on this test's 0.3 mesh (refine_radius 0.5 a) n = 3 came first (0.77285), on
// studies/cap_pressure_buckling.py's 0.3 mesh n = 4 (0.77146). Measured on the 0.2 mesh (14045
// unknowns, 287 s of CPU): n = 4 (94 % of the ring's power) at 0.76653 (+0.07 %; the study's
// 0.2 mesh +0.32 %). Asserted within 0.5 %: the 0.2 meshes' own error (below 0.35 %, halved
// from the 0.3 meshes' as e^2) and the shallow-theory model difference. A long test.
TEST(CapPressureBifurcation, Lambda8_AsymmetricBifurcationFirst_Huang1964) {
  if (!verification::long_tests_enabled()) GTEST_SKIP() << "set SHELLINDENT_LONG_TESTS=1 to run";
  constexpr double kReference = 0.766004;
  const FirstCriticalPoint c = first_critical_point(8.0, 0.2);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(c.criticality, cont::Criticality::kBifurcation);
  EXPECT_EQ(c.wave_number, 4);
  EXPECT_LT(c.asymmetry, 1e-6);
  EXPECT_NEAR(c.pressure_ratio / kReference, 1.0, kConvergedTolerance);
}

}  // namespace
}  // namespace si
