// Shared set-up of the linear shell verification benchmarks (tests/verification/): a model is a
// mesh with supports, loads and a resultant law; it is solved by the production static run
// (analysis/static_run.hpp) in Kinematics::kLinear (one load level: K q = f). Distributed loads of
// a given surface traction are turned into consistent nodal forces here (3 x 3 Gauss points on the
// bilinear map, f_a = integral N_a t dA) and applied as per-node point loads on one-node sets.
// Reference data: ../shared/benchmarks/linear.md (copied into each test with its source).
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "analysis/static_run.hpp"
#include "model/assembler.hpp"
#include "model/loads.hpp"
#include "model/mesh.hpp"
#include "model/supports.hpp"
#include "section/gauss_legendre.hpp"
#include "shell/shape4.hpp"
#include "shell/shell_element.hpp"

namespace si::verification {

struct BenchmarkModel {
  Mesh mesh;
  std::vector<Support> supports;
  Loads loads;
  ShellLaw law;
};

struct BenchmarkSolution {
  std::vector<NodeState> state;  // linear solution: u and the linearised directors
  StepResult step;               // energy, reactions, applied force
  double seconds = 0;            // wall time of dof map + solve
};

// Traction (force per unit reference area, N/mm^2) at a point of the reference mid-surface.
using Traction = std::function<Vector3d(const Vector3d& position)>;

// Consistent nodal forces of `traction` over every element: f_a = sum_g N_a t(x_g) |x_xi x
// x_eta| w_g with 3 x 3 Gauss points (exact for a constant traction on flat elements, and
// fourth-order accurate for smooth ones). One row per node.
inline std::vector<Vector3d> consistent_nodal_forces(const Mesh& mesh, const Traction& traction) {
  std::vector<Vector3d> f(mesh.nodes.size(), Vector3d::Zero());
  const GaussRule rule = gauss_legendre(3);
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const std::array<Vector3d, 4> X = element_corners(mesh, e);
    for (std::size_t i = 0; i < rule.points.size(); ++i)
      for (std::size_t j = 0; j < rule.points.size(); ++j) {
        const Shape4 s = evaluate_shape4(ShapeSet::kBilinear, rule.points[i], rule.points[j]);
        Vector3d x = Vector3d::Zero(), x_xi = Vector3d::Zero(), x_eta = Vector3d::Zero();
        for (int a = 0; a < 4; ++a) {
          x += s.N(a) * X[a];
          x_xi += s.N_xi(a) * X[a];
          x_eta += s.N_eta(a) * X[a];
        }
        const Vector3d t =
            traction(x) * x_xi.cross(x_eta).norm() * rule.weights[i] * rule.weights[j];
        for (int a = 0; a < 4; ++a) f[mesh.elements[e][a]] += s.N(a) * t;
      }
  }
  return f;
}

// Adds the consistent nodal forces of `traction` to the model's loads, as per-node point loads
// on one-node sets "surface_load_<node>".
inline void add_surface_traction(BenchmarkModel& model, const Traction& traction) {
  const std::vector<Vector3d> f = consistent_nodal_forces(model.mesh, traction);
  for (int n = 0; n < model.mesh.num_nodes(); ++n) {
    if (f[n].isZero(0)) continue;
    const std::string name = "surface_load_" + std::to_string(n);
    set_node_set(model.mesh, name, {n});
    model.loads.points.push_back({name, f[n], true});
  }
}

// Solves the model with the production linear path: supports -> dof map, run_static with
// Kinematics::kLinear and one load level.
inline BenchmarkSolution solve_linear(const BenchmarkModel& model,
                                      ElementType element_type = ElementType::kMitc4) {
  const auto start = std::chrono::steady_clock::now();
  const auto element = make_shell_element(element_type);
  const DofMap dofs = make_dof_map(model.mesh, model.supports);
  StaticSettings settings;
  settings.steps = 1;
  StaticResult result =
      run_static(model.mesh, dofs, *element, model.law, Kinematics::kLinear, model.loads, settings);
  EXPECT_EQ(result.failure, "");
  BenchmarkSolution out;
  out.state = std::move(result.state);
  if (!result.steps.empty()) out.step = result.steps.back();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

// The single node of a one-node set.
inline int single_node(const Mesh& mesh, const std::string& set) {
  const std::vector<int>& nodes = mesh.node_sets.at(set);
  EXPECT_EQ(nodes.size(), 1u) << "node set " << set;
  return nodes.front();
}

// Global equilibrium of a solved model: the reactions balance the applied loads.
inline void expect_equilibrium(const BenchmarkSolution& s) {
  const double scale = std::max(s.step.applied_force.cwiseAbs().maxCoeff(), 1e-300);
  EXPECT_LT((s.step.reaction_force + s.step.applied_force).cwiseAbs().maxCoeff(), 1e-8 * scale);
}

// One row of a printed convergence table: mesh, computed value, normalised value, error, time.
struct ConvergenceRow {
  std::string mesh;
  double value = 0;
  double seconds = 0;
};

inline void print_convergence_table(const std::string& title, double reference,
                                    const std::vector<ConvergenceRow>& rows) {
  std::printf("\n%s (reference %.6g)\n", title.c_str(), reference);
  std::printf("| mesh | computed | computed / reference | error %% | time s |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const ConvergenceRow& r : rows)
    std::printf("| %s | %.6g | %.4f | %+.2f | %.3f |\n", r.mesh.c_str(), r.value,
                r.value / reference, 100 * (r.value / reference - 1), r.seconds);
}

}  // namespace si::verification
