// The shell in the indentation problem (indentation_problem.hpp): its unknowns, the chart
// coordinates x of the free dofs (model/shell_chart.hpp; for linear kinematics the element's
// linear-mode dofs, the same numbers), its equilibrium rows r(x) and their Jacobian, and what the
// results need of it (energy, support reaction, nodal curvatures, tributary areas).
//
// Kinematics decide all of it, here and nowhere else in the problem:
//  * nonlinear: r and K assembled at x (ChartAssembly, once per x), the Jacobian K T + D of the
//    chart, the exact gap of a node (contact/node_gap.hpp);
//  * linear: K of the reference state, r = K x, no chart transform, the gap linearised about the
//    reference state (the paper's eqs 73-80).
#pragma once

#include <vector>

#include "contact/indenter.hpp"
#include "contact/node_gap.hpp"
#include "core/sparse.hpp"
#include "model/assembler.hpp"
#include "model/chart_assembly.hpp"
#include "model/dof_map.hpp"
#include "model/shell_chart.hpp"
#include "model/shell_model.hpp"

namespace si {

class ShellPart {
 public:
  // Keeps a reference to the model. `direction`: the unit direction of travel, along which the
  // support reaction is reported. threads: element assembly (0 = OpenMP default).
  ShellPart(const ShellModel& model, const Vector3d& direction, int threads);

  int size() const { return chart_.size(); }
  bool nonlinear() const { return model_.kinematics == Kinematics::kNonlinear; }
  const ShellModel& model() const { return model_; }
  const DofMap& dofs() const { return dofs_; }
  const Assembler& assembler() const { return assembler_; }
  // K at the reference state: the Jacobian's pattern, and the tangent of linear kinematics.
  const SparseMatrix& reference_tangent() const { return reference_tangent_; }

  // r(x) on the free dofs; returns the node states at x (valid until the next call). Nonlinear
  // kinematics: the force and tangent at x stay cached for tangent().
  const std::vector<NodeState>& force(const Eigen::VectorXd& x, Eigen::VectorXd& r_free);
  // dr/dx before the chart transform, at the x of the last force().
  const SparseMatrix& tangent(const Eigen::VectorXd& x);
  // J's shell columns become K T + D (nonlinear; returns the blocks T), or stay (linear: none).
  std::vector<ShellChart::RotationBlock> to_chart(const Eigen::VectorXd& x,
                                                  const Eigen::VectorXd& r_free,
                                                  SparseMatrix& J) const;
  // Node states at x (a fresh copy).
  std::vector<NodeState> states(const Eigen::VectorXd& x) const;

  // The gap of mesh node `node` to `indenter` moving along `direction` at `travel` (mm): exact
  // (nonlinear, with the gradient's derivative if asked) or linearised (linear).
  NodeGap gap(const Indenter& indenter, const Vector3d& direction,
              const NodeContactGeometry& geometry, int node, const std::vector<NodeState>& s,
              double travel, double guess, bool derivative) const;

  // The gap of mesh node `node` to the fixed plane {normal . y = level} (contact/node_gap.hpp),
  // exact or linearised like gap().
  NodeGap plane_gap(const Vector3d& normal, double level, const NodeContactGeometry& geometry,
                    int node, const std::vector<NodeState>& s, bool derivative) const;

  // Whole-shell strain energy (N mm) and support reaction along the direction of travel (N).
  void energy_and_reaction(const Eigen::VectorXd& x, double& energy, double& reaction);
  // k11, k12 + k21, k22 at mesh node `node`, averaged over its elements (1/mm).
  Vector3d curvature(const std::vector<NodeState>& s, int node) const;
  // The relative energy-norm discretisation error of the state (model/recovery_error.hpp).
  double error_estimate(const std::vector<NodeState>& s) const;
  // The elements that contain mesh node `node`.
  const std::vector<int>& node_elements(int node) const { return node_elements_[node]; }
  // A quarter of each adjacent element's area, mm^2.
  double tributary_area(int node) const { return tributary_area_[node]; }

  long tangent_assemblies() const { return assembly_.tangent_assemblies(); }
  long force_assemblies() const { return assembly_.force_assemblies(); }

 private:
  void build_reaction_row();
  // Linear kinematics: node `node`'s chart coordinates at s (its linear mode's dofs).
  Vector5d chart_coordinates(int node, const std::vector<NodeState>& s) const;

  const ShellModel& model_;
  DofMap dofs_;
  Assembler assembler_;
  ShellChart chart_;
  ChartAssembly assembly_;  // nonlinear kinematics: force and tangent at the last x
  SparseMatrix reference_tangent_;
  std::vector<NodeState> linear_states_;  // linear kinematics: node states at the last x
  Vector3d direction_;
  // Linear kinematics: the support reaction along the direction of travel is r_e . x.
  Eigen::VectorXd reaction_row_;
  std::vector<double> tributary_area_;           // per mesh node, mm^2
  std::vector<std::vector<int>> node_elements_;  // per mesh node: the elements containing it
  std::vector<int> support_elements_;            // elements with a prescribed translation
};

}  // namespace si
