// A clamped shallow spherical cap under uniform external pressure, whole (not a quarter) so that
// the modes that are not axisymmetric exist: the load problem's stability along the
// pseudo-arclength path (analysis/load_problem.hpp, load_stability.cpp) finds the first loss of
// stability, classifies it (limit point or bifurcation) and gives its mode, whose circumferential
// wave number n is read by a Fourier analysis of the mode's normal displacement on a ring.
//
// The classical results (Huang 1964, "Unsymmetrical buckling of thin shallow spherical shells",
// J. Appl. Mech. 31, 447-457; Weinitschke 1965; Fitch & Budiansky 1970, AIAA J. 8, 686-693;
// Bushnell 1985, "Computerized buckling analysis of shells", ch. on spherical caps): with the
// geometric parameter lambda = 2 [3 (1 - nu^2)]^(1/4) sqrt(H / h) (H the rise, h the thickness)
// and the classical pressure p_cl = 2 E h^2 / (R^2 sqrt(3 (1 - nu^2))) of the complete sphere,
//   - for lambda below about 5.5 the clamped cap loses stability at the axisymmetric limit point
//     (snap-through, n = 0);
//   - above it, it bifurcates into a non-axisymmetric mode (n >= 2) before the limit point, at a
//     pressure of the order of 0.7 - 0.9 p_cl, n growing with lambda.
// What these tests assert is that qualitative statement (kind of the first critical point, n = 0
// or n >= 2, and the pressure band); the quantitative table of Huang (p_cr / p_cl and n per
// lambda, reproduced as Table 3 of Teng & Rotter 1989, Comput. Struct. 32, 453-475, for lambda =
// 6 ... 16 at nu = 1/3) could not be retrieved for this work, and the computed values are
// recorded in docs/verification.md for that comparison (pending).
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
constexpr double kSphere = 100.0;   // mm

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
FirstCriticalPoint first_critical_point(double lambda, double element_size) {
  const double a = base_radius(lambda);
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

// lambda = 4: below Huang's threshold the first critical point is the axisymmetric snap.
TEST(CapPressureBifurcation, Lambda4_AxisymmetricLimitPointFirst_Huang1964) {
  const FirstCriticalPoint c = first_critical_point(4.0, 3.0);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(c.criticality, cont::Criticality::kLimitPoint);
  EXPECT_EQ(c.wave_number, 0);
  EXPECT_LT(c.asymmetry, 1e-6);  // the follower pressure with a clamped edge is conservative
}

// lambda = 8: above it, an asymmetric bifurcation (n >= 2) comes before the limit point.
// Measured: bifurcation at p / p_cl = 0.77648, n = 4 (91 % of the ring's power), 18 points; a
// long test (9 min wall on the shared machine at load 15; several minutes of CPU).
TEST(CapPressureBifurcation, Lambda8_AsymmetricBifurcationFirst_Huang1964) {
  if (!verification::long_tests_enabled()) GTEST_SKIP() << "set SHELLINDENT_LONG_TESTS=1 to run";
  const FirstCriticalPoint c = first_critical_point(8.0, 4.0);
  ASSERT_TRUE(c.found);
  EXPECT_EQ(c.criticality, cont::Criticality::kBifurcation);
  EXPECT_GE(c.wave_number, 2);
  EXPECT_GT(c.pressure_ratio, 0.6);
  EXPECT_LT(c.pressure_ratio, 1.0);
  EXPECT_LT(c.asymmetry, 1e-6);
}

}  // namespace
}  // namespace si
