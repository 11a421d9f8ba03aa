// The 3-D recovery fed by our MITC4 shell solution on a mesh (issue 16), against Pagano's exact
// 3-D elasticity solution of the simply supported square [0/90/0] plate under a sinusoidal load
// (Pagano 1970; tests/section/pagano_plate.hpp). The 2-D model is the VAM section's A_R and G on a
// full-plate mesh of mitc4 elements (no load coupling Fbar: the static path has none); R and its
// derivatives at a point come from a cubic least-squares fit of the element-averaged nodal strains
// over the nearest nodes (model/patch_fit.hpp). Interior points are used, where the patch is
// centred: sigma_x, sigma_y at (a/2, a/2), tau_xy at (a/4, a/4), tau_xz at (a/4, a/2), tau_yz at
// (a/2, a/4); the exact values there are the amplitudes times the trigonometric factors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "../section/laminate_fixtures.hpp"
#include "../section/pagano_plate.hpp"
#include "core/constants.hpp"
#include "model/nodal_resultants.hpp"
#include "model/patch_fit.hpp"
#include "model/plate_meshes.hpp"
#include "section/through_thickness_recovery.hpp"
#include "section/vam_section.hpp"
#include "shell_benchmark_support.hpp"

namespace si::verification {
namespace {

Laminate pagano_layup() {
  return testing::make_laminate(testing::pagano_material(), 1.0 / 3.0, {0, 90, 0});
}

// Nodal strains of the mitc4 solution of the plate of side a = S (h = 1) under
// q0 sin(pi x/a) sin(pi y/a), q0 = S^-4 (small rotations), on an n x n full-plate mesh.
struct MeshSolution {
  Mesh mesh;
  Eigen::MatrixXd strains;  // one row per node: R (6), gamma (2)
  double q0;
};

MeshSolution solve_mesh(const VamSection& section, double S, int n) {
  const double a = S, q0 = std::pow(S, -4);
  BenchmarkModel m;
  m.mesh = rectangular_plate_mesh(a, a, n, n);
  // Pagano's simple support (test_laminate_navier.cpp): v = w = 0 and the normal's rotation about
  // the edge free on x = 0, a; u = w = 0 on y = 0, a.
  m.supports = {{SupportKind::kFixedDofs, "edge_x0", -1, {1, 2, 3}},
                {SupportKind::kFixedDofs, "edge_x1", -1, {1, 2, 3}},
                {SupportKind::kFixedDofs, "edge_y0", -1, {0, 2, 4}},
                {SupportKind::kFixedDofs, "edge_y1", -1, {0, 2, 4}}};
  m.law.A_R = section.A_R;
  m.law.G = section.G;
  add_surface_traction(m, [&](const Vector3d& x) {
    return Vector3d(0, 0, -q0 * std::sin(kPi * x.x() / a) * std::sin(kPi * x.y() / a));
  });
  const BenchmarkSolution s = solve_linear(m);
  const auto element = make_shell_element(ElementType::kMitc4);
  const DofMap dofs = make_dof_map(m.mesh, m.supports);
  const Assembler assembler(m.mesh, dofs, *element, m.law, Kinematics::kLinear, 1);
  MeshSolution out{m.mesh, nodal_strains(m.mesh, assembler, *element, s.state), q0};
  return out;
}

// The recovery's state at (x, y) from the patch fit of the nodal strains.
PlateState fitted_state(const MeshSolution& sol, double x, double y, int degree, int nodes,
                        bool refined) {
  std::vector<Vector2d> points;
  for (const Vector3d& p : sol.mesh.nodes) points.emplace_back(p.x(), p.y());
  const PatchFit f = fit_patch(points, sol.strains.leftCols<6>(), Vector2d(x, y), degree, nodes);
  PlateState s;
  s.R = f.value;
  s.dR = {f.d1[0], f.d1[1]};
  if (refined) {
    s.d2R = std::array<Vector6d, 3>{f.d2[0], f.d2[1], f.d2[2]};
    s.d3R = std::array<Vector6d, 4>{f.d3[0], f.d3[1], f.d3[2], f.d3[3]};
  }
  const double a = sol.mesh.nodes.back().x();  // the far corner is (a, a)
  s.t_top = -sol.q0 * std::sin(kPi * x / a) * std::sin(kPi * y / a);
  return s;
}

struct Peaks {
  double sx, sy, txy, txz, tyz;
};

template <class F>
double peak_over_z(const Laminate& laminate, F stress_at) {
  const std::vector<double> z = laminate.interfaces();
  double peak = 0;
  for (int k = 0; k + 1 < static_cast<int>(z.size()); ++k)
    for (int i = 0; i <= 30; ++i)
      peak = std::max(peak, std::abs(stress_at(k, z[k] + (z[k + 1] - z[k]) * i / 30.0)));
  return peak;
}

Peaks exact_peaks(const Laminate& laminate, double a, double q0) {
  const testing::PaganoPlate plate(laminate, a, a, q0);
  const double c45 = std::cos(kPi / 4);  // cos(pi/4) = sin(pi/4)
  auto peak = [&](double testing::PaganoPoint::*member, double factor) {
    return factor * peak_over_z(laminate, [&](int k, double z) { return plate.at(z, k).*member; });
  };
  return {peak(&testing::PaganoPoint::sigma_xx, 1), peak(&testing::PaganoPoint::sigma_yy, 1),
          peak(&testing::PaganoPoint::tau_xy, c45 * c45), peak(&testing::PaganoPoint::tau_xz, c45),
          peak(&testing::PaganoPoint::tau_yz, c45)};
}

Peaks mesh_peaks(const Laminate& laminate, const VamSection& section, const MeshSolution& sol,
                 int degree, int nodes, bool refined) {
  const double a = sol.mesh.nodes.back().x();
  auto peak = [&](double x, double y, int component) {
    const PlateState s = fitted_state(sol, x, y, degree, nodes, refined);
    return peak_over_z(laminate, [&](int k, double z) {
      return recover_point(section, s, k, z).stress(component);
    });
  };
  return {peak(a / 2, a / 2, 0), peak(a / 2, a / 2, 2), peak(a / 4, a / 4, 1),
          peak(a / 4, a / 2, 3), peak(a / 2, a / 4, 4)};
}

void print_row(const char* name, double S, int n, const Peaks& p, const Peaks& e) {
  std::printf("| %g | %d x %d | %s | %+.1f %% | %+.1f %% | %+.1f %% | %+.1f %% | %+.1f %% |\n", S,
              n, n, name, 100 * (p.sx / e.sx - 1), 100 * (p.sy / e.sy - 1),
              100 * (p.txy / e.txy - 1), 100 * (p.txz / e.txz - 1), 100 * (p.tyz / e.tyz - 1));
}

double worst(const Peaks& p, const Peaks& e) {
  return std::max({std::abs(p.sx / e.sx - 1), std::abs(p.sy / e.sy - 1),
                   std::abs(p.txy / e.txy - 1), std::abs(p.txz / e.txz - 1),
                   std::abs(p.tyz / e.tyz - 1)});
}

// Acceptance with a mesh: at S = 10 the refined recovery from the mitc4 solution on a 32 x 32
// full-plate mesh is within 3 % of Pagano for every peak; the first-order recovery is not.
TEST(PaganoMeshRecovery, Mitc4_32x32_RefinedWithin3PercentAtS10) {
  const Laminate laminate = pagano_layup();
  const VamSection section = analyze_vam(laminate);
  const double S = 10;
  const MeshSolution sol = solve_mesh(section, S, 32);
  const Peaks exact = exact_peaks(laminate, S, sol.q0);
  const Peaks first = mesh_peaks(laminate, section, sol, 3, 25, false);
  const Peaks refined = mesh_peaks(laminate, section, sol, 3, 25, true);
  print_row("mitc4, first-order", S, 32, first, exact);
  print_row("mitc4, refined", S, 32, refined, exact);
  EXPECT_GT(worst(first, exact), 0.1);
  EXPECT_LT(worst(refined, exact), 0.03);
}

// The table of docs/theory/failure.md: mesh and patch size (printed, not checked).
TEST(PaganoMeshRecovery, DISABLED_ComparisonTable_Mitc4) {
  const Laminate laminate = pagano_layup();
  const VamSection section = analyze_vam(laminate);
  for (double S : {4.0, 10.0}) {
    for (int n : {16, 32, 64}) {
      const MeshSolution sol = solve_mesh(section, S, n);
      const Peaks exact = exact_peaks(laminate, S, sol.q0);
      print_row("first-order, cubic fit 25 nodes", S, n,
                mesh_peaks(laminate, section, sol, 3, 25, false), exact);
      print_row("refined, cubic fit 25 nodes", S, n,
                mesh_peaks(laminate, section, sol, 3, 25, true), exact);
      print_row("refined, cubic fit 49 nodes", S, n,
                mesh_peaks(laminate, section, sol, 3, 49, true), exact);
      print_row("refined, quartic fit 49 nodes", S, n,
                mesh_peaks(laminate, section, sol, 4, 49, true), exact);
    }
  }
}

}  // namespace
}  // namespace si::verification
