// A load-controlled shell as a continuation problem in the load factor lambda
// (continuation/problem.hpp): the equilibrium of a shell under loads that grow proportionally,
//     F(x, lambda) = f_int(x, lambda u_p) - lambda f_ext(x) = 0        (free dofs),
// x the shell's chart coordinates (model/shell_chart.hpp), u_p the prescribed translations
// (supports.hpp: a non-zero prescribed value grows with lambda like the loads), f_ext the dead
// loads plus the follower pressures at the current positions (loads.hpp).
//
// Nonlinear kinematics: the Jacobian is exact, dF/dx = (K - lambda K_p) T(x) + D(x, F) with K_p
// the follower pressure's load stiffness and T, D the chart transform of shell_chart.hpp; it is
// unsymmetric, so it is factored by UMFPACK (or KLU). dF/dlambda = -f_ext(x), exact when no
// prescribed value is non-zero (else the continuation's central difference of F, second order).
// The pseudo-arclength method follows the path through limit points of the load (snap-through)
// and of the displacement (snap-back), which load control cannot (Riks 1979; Crisfield 1981).
// The chart is singular where a node has turned by pi from its base (shell_chart.hpp), so a node
// that turns further (a strip rolled into a circle) is re-based on the way: adapt() re-bases
// every node turned by more than pi/2 at an accepted point; the continuation then re-solves
// there (a converged state: no iteration) and recomputes the tangent in the new chart, dropping
// the secant history (continuation/problem.hpp). x then holds the rotations from the new base;
// a point located before the re-basing (an event) is read with the base of its time
// (point_state_with_base()).
//
// Linear kinematics: F = K x + lambda (K_fp u_p - f_ext) with K the reference stiffness,
// factored once (CHOLMOD, or UMFPACK if K is not positive definite); the node states are those
// the element's linear mode reads back exactly (rotate_node(reference, a, b), shell_element.hpp)
// and a follower pressure acts at the reference positions, as a dead one.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "continuation/problem.hpp"
#include "model/assembler.hpp"
#include "model/chart_assembly.hpp"
#include "model/dof_map.hpp"
#include "model/loads.hpp"
#include "model/shell_chart.hpp"
#include "model/supports.hpp"
#include "solvers/linear_solver.hpp"

namespace si {

// A monitored displacement: the mean of u . direction over the nodes of a node set, mm.
struct DisplacementMonitor {
  std::string name;
  std::string node_set;
  Vector3d direction = Vector3d::UnitZ();
};

struct LoadProblemOptions {
  std::vector<DisplacementMonitor> displacements;  // monitors after "load_factor"
  Kinematics kinematics = Kinematics::kNonlinear;
  // The Jacobian's solver. Nonlinear kinematics: umfpack or klu (K T + D is unsymmetric; cholmod
  // is refused). Linear: cholmod falls back to umfpack once if K is not positive definite.
  LinearSolverKind linear_solver = LinearSolverKind::kUmfpack;
  int threads = 0;  // element assembly (0 = OpenMP default)
};

// The equilibrium quantities of one point, whole dof vectors of the model (not of a whole shell
// of which it is a quarter).
struct LoadPointState {
  std::vector<NodeState> states;
  Eigen::VectorXd internal_force;  // every dof; at the prescribed ones minus the reactions
  Eigen::VectorXd external_force;  // lambda f_ext, every dof
  double energy = 0;               // strain energy, N mm
};

class LoadProblem : public cont::Problem {
 public:
  // Keeps references to mesh and element. Throws an input error for invalid loads or monitor
  // node sets, and for cholmod with nonlinear kinematics.
  LoadProblem(const Mesh& mesh, DofMap dofs, const ShellElement& element, const ShellLaw& law,
              const Loads& loads, LoadProblemOptions options);
  // Supports with zero values.
  LoadProblem(const Mesh& mesh, const std::vector<Support>& supports, const ShellElement& element,
              const ShellLaw& law, const Loads& loads, LoadProblemOptions options);
  ~LoadProblem() override;

  int size() const override;
  bool residual(const cont::Vector& x, double lambda, cont::Vector& F) override;
  bool factorize(const cont::Vector& x, double lambda) override;
  bool solve(cont::Vector& b) override;
  bool residual_p(const cont::Vector& x, double lambda, cont::Vector& out) override;
  // Arclength metric: the mean square of the chart coordinates, <a, b> = a.b / n (mm^2 for the
  // translations; the rotations, in rad, are small against them), so an arclength step is the
  // RMS nodal displacement increment; the load factor enters with Settings::parameter_weight (mm
  // per unit load factor).
  double inner(const cont::Vector& a, const cont::Vector& b) const override;
  // Nonlinear kinematics: re-bases the chart at x (see above); true if a node was re-based.
  bool adapt(cont::Vector& x, double lambda) override;
  // Stability of a converged point (load_stability.cpp; docs/theory/continuation.md 12): the
  // symmetric part of the chart Hessian of the potential, T' dF/dx (F = 0 there), its negative
  // count and lowest eigenpairs (chart coordinates). Linear kinematics: K, always stable.
  bool provides_stability() const override { return true; }
  bool stability(const cont::Vector& x, double lambda, int modes, cont::Stability& out) override;
  // What stability() analyses: H = (T' J + J' T) / 2 and the relative size of the skew part
  // |T'J - J'T|_F / |T'J|_F dropped from it (0 for a conservative load at equilibrium).
  struct StabilityMatrix {
    SparseMatrix H;
    double asymmetry = 0;
  };
  StabilityMatrix stability_matrix(const cont::Vector& x, double lambda);

  // "load_factor", then the displacement monitors in options order.
  std::vector<std::string> monitor_names() const override;
  cont::Vector monitors(const cont::Vector& x, double lambda) override;

  // The undeformed state (the solution at lambda = 0).
  cont::Vector initial_point() const { return cont::Vector::Zero(size()); }
  std::vector<NodeState> node_states(const cont::Vector& x, double lambda = 1.0) const;
  // Forces, energy and states at a point (one force assembly unless cached).
  LoadPointState point_state(const cont::Vector& x, double lambda);
  // The same for x in the chart with the given base frames (a chart_base() of an earlier time).
  LoadPointState point_state_with_base(const std::vector<NodeState>& base, const cont::Vector& x,
                                       double lambda);
  // The chart's base frames (ShellChart::base) and the number of adapt() calls that re-based it.
  const std::vector<NodeState>& chart_base() const { return chart_.base(); }
  int rebasings() const { return rebasings_; }
  const DofMap& dofs() const { return dofs_; }
  // f_ext on the free dofs at load factor 1 and the reference positions.
  const Eigen::VectorXd& load_vector() const { return load_; }
  // The magnitude of the forces that balance at a solution, for the Newton tolerance, at load
  // factor 1: the largest free-dof load and, with non-zero prescribed displacements, the largest
  // internal force (reaction) of the linear solution (N); 1 if both vanish.
  double force_scale() const { return force_scale_; }
  // The roundoff floor of the residual at load factor 1 (linear_scales() in the .cpp; linear
  // kinematics: at least the residual of the linear solution, linear_residual()), N.
  double roundoff_force() const { return roundoff_force_; }
  // The solver of the last factorization.
  LinearSolverKind linear_solver() const { return solver_->kind(); }
  // The last numerical error met by residual() or factorize() (an element's, a singular
  // matrix'); empty if none. The continuation only sees `false`; a caller reports this.
  const std::string& last_error() const { return last_error_; }

 private:
  bool nonlinear() const { return options_.kinematics == Kinematics::kNonlinear; }
  bool has_prescribed_values() const;
  double linear_scales();
  double linear_residual(LinearSolver& solver);
  // lambda f_ext at the states of the last assembly, every dof.
  Eigen::VectorXd external_force(double lambda) const;
  const Assembly& assembly_at(const cont::Vector& x, double lambda, bool tangent);
  void factorize_matrix();
  // Nonlinear kinematics: dF/dx = (K - lambda K_p) T + D at (x, lambda), assembled; `rotations`
  // receives the chart's 2x2 blocks T.
  SparseMatrix chart_jacobian(const cont::Vector& x, double lambda,
                              std::vector<ShellChart::RotationBlock>& rotations);

  const Mesh& mesh_;
  Loads loads_;
  LoadProblemOptions options_;
  DofMap dofs_;
  Assembler assembler_;
  ShellChart chart_;
  ChartAssembly shell_;         // force and tangent at the last (x, lambda)
  Eigen::VectorXd fixed_load_;  // every dof, load factor 1 (linear: with the followers)
  Eigen::VectorXd load_;        // free dofs
  double force_scale_ = 1;
  double roundoff_force_ = 0;
  std::vector<std::vector<int>> monitor_nodes_;  // per displacement monitor
  SparseMatrix jacobian_;
  std::unique_ptr<LinearSolver> solver_;
  bool factorized_ = false;  // linear kinematics: K is factored once
  // Nonlinear: the point of the last factorize() and its chart blocks (stability() reuses them).
  cont::Vector factored_x_;
  double factored_lambda_ = 0;
  std::vector<ShellChart::RotationBlock> rotations_;
  int rebasings_ = 0;
  std::string last_error_;
};

}  // namespace si
