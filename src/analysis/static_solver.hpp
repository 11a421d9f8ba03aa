// Load-controlled static analysis: the load factor lambda goes from 0 to 1 in `steps` equal
// increments and scales every load (loads.hpp) and every prescribed displacement (supports.hpp).
//
// Nonlinear kinematics: full Newton at each load factor on the free dofs, residual
// r = f_int(state) - lambda f_ext(state). The solved increment q updates each node
// multiplicatively: translations added, rotations by rotate_node(state, q_rot_v1, q_rot_v2)
// (shell/director.hpp), i.e. about the node's current axes. Converged when both the relative
// residual |r| / max(|lambda f_ext|, |f_int|) (all dofs, so reactions count) and the energy
// ratio |q_k . r_k| / |q_0 . r_0| are below `tolerance`. A step that fails (too many iterations,
// non-finite or exploding residual) is retried from the last converged state with half the
// increment, at most max_halvings times in a row; every converged (sub)step is recorded.
//
// Linear kinematics: K is assembled and factorized once at the reference state and each load
// level is one solve, K_ff q_f = lambda f - f_int(prescribed q_p) (plus two force-only
// assemblies: f_int of the prescribed displacements, and the final f_int for the reactions).
// The state is the reference state plus u += q_u and, per node, one
// rotate_node(reference, a, b): the element's linear mode reads the rotation dofs back exactly
// from it (shell_element.hpp); follower pressures act at the reference positions (as dead ones).
//
// Linear solver: `linear_solver` for symmetric tangents; a follower pressure (non-symmetric
// tangent) uses UMFPACK from the start, and if CHOLMOD finds the tangent not positive definite
// (past a limit point) the solver switches to UMFPACK for the rest of the run. A singular
// tangent (both solvers fail) is not retried: it usually means missing supports.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "model/assembler.hpp"
#include "model/loads.hpp"
#include "solvers/linear_solver.hpp"

namespace si {

struct StaticSettings {
  int steps = 10;
  int max_iterations = 25;
  double tolerance = 1e-8;  // relative residual and energy ratio
  bool halve_on_failure = true;
  int max_halvings = 5;
  LinearSolverKind linear_solver = LinearSolverKind::kCholmod;  // cholmod | umfpack
  std::vector<int> record_nodes;  // nodes whose displacement each StepResult keeps

  // Throws an input error naming the bad field.
  void validate() const;
};

struct StepResult {
  double load_factor = 0;
  int iterations = 0;                          // Newton iterations (linear solves) of this step
  double energy = 0;                           // strain energy, N mm
  std::vector<Vector3d> displacements;         // of StaticSettings::record_nodes, mm
  Eigen::VectorXd reactions;                   // at DofMap::prescribed_dofs(), in that order
  Vector3d reaction_force = Vector3d::Zero();  // sum of the translational reactions, N
  Vector3d applied_force = Vector3d::Zero();   // sum of the applied nodal forces, N
  std::vector<double> residual_history;        // relative residual at each iteration
  LinearSolverKind linear_solver = LinearSolverKind::kCholmod;  // of the last factorization
};

// Called after each converged (sub)step with the result and the converged state. Returning
// false stops the analysis (solve() then returns normally).
using StepCallback = std::function<bool(const StepResult&, const std::vector<NodeState>&)>;

class StaticSolver {
 public:
  // Keeps references to mesh, dof map and element. Validates settings and loads.
  StaticSolver(const Mesh& mesh, const DofMap& dofs, const ShellElement& element, ShellLaw law,
               Kinematics kinematics, Loads loads, StaticSettings settings, int threads = 0);
  ~StaticSolver();

  // Runs from `state` (usually reference_state(mesh)) at lambda = 0; on return `state` is the
  // last converged state. A failed step throws a numerical error that names the load factor and
  // the reason; steps() still holds every converged step.
  const std::vector<StepResult>& solve(std::vector<NodeState>& state,
                                       const StepCallback& callback = {});
  const std::vector<StepResult>& steps() const { return steps_; }

 private:
  struct Attempt {
    bool converged = false;
    std::string reason;
  };
  void solve_linear(std::vector<NodeState>& state, const StepCallback& callback);
  void solve_nonlinear(std::vector<NodeState>& state, const StepCallback& callback);
  Attempt newton(std::vector<NodeState>& state, double lambda, StepResult& result);
  void set_prescribed(std::vector<NodeState>& state, double lambda) const;
  Eigen::VectorXd external_force(const std::vector<NodeState>& state, double lambda) const;
  void factorize(const SparseMatrix& K);
  void finish_step(const std::vector<NodeState>& state, double lambda, const Assembly& assembly,
                   const Eigen::VectorXd& f_ext, StepResult& result) const;

  const Mesh& mesh_;
  const DofMap& dofs_;
  Loads loads_;
  StaticSettings settings_;
  Assembler assembler_;
  Assembly assembly_;  // reused by every assembly (the tangent's pattern is allocated once)
  Eigen::VectorXd fixed_load_;
  std::unique_ptr<LinearSolver> solver_;
  std::vector<StepResult> steps_;
};

}  // namespace si
