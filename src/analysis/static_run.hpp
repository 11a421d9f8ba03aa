// Load-controlled static analysis: the load problem (load_problem.hpp: every load and every
// prescribed displacement times the load factor lambda) traced from lambda = 0 through
// continuation/, the one load-controlled driver of the code.
//
// natural: lambda steps to 1/steps, 2/steps, ..., 1, each hit exactly and recorded; Newton
// (continuation/'s KINSOL corrector, from the tangent predictor) at each; a step that fails is
// retried with half the increment, at most max_halvings times in a row, and every converged
// (sub)step is recorded; the increment then grows back to the nominal one. Cannot pass a limit
// point of the load: there the run ends with the steps it converged.
// pseudo_arclength: steps in arclength (mm: the RMS nodal displacement increment, and
// parameter_weight mm per unit load factor; LoadProblem::inner) through limit points of the
// load and of the displacement (snap-through, snap-back), up to lambda = load_factor_max; the
// limit points of lambda are located (events).
//
// Convergence: ||F||_inf <= tolerance * max(||F at the predictor||_inf, force scale), the force
// scale being the largest free-dof force of the loads or of the prescribed displacements at
// lambda = 1 (LoadProblem::force_scale).
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "analysis/static_spec.hpp"
#include "continuation/branch.hpp"
#include "model/assembler.hpp"
#include "model/loads.hpp"

namespace si {

// A converged point of the run (or an event located between two of them).
struct StepResult {
  double load_factor = 0;
  int iterations = 0;                          // Newton iterations of this step
  double energy = 0;                           // strain energy, N mm
  std::vector<Vector3d> displacements;         // of StaticSettings::record_nodes, mm
  Eigen::VectorXd reactions;                   // at DofMap::prescribed_dofs(), in that order
  Vector3d reaction_force = Vector3d::Zero();  // sum of the translational reactions, N
  Vector3d applied_force = Vector3d::Zero();   // sum of the applied nodal forces, N
  LinearSolverKind linear_solver = LinearSolverKind::kCholmod;  // of the last factorization
  // StaticSettings::stability only (else -1, false, NaN): the number of negative eigenvalues of
  // the chart Hessian, no negative and no zero one, and the lowest eigenvalue (N/mm).
  int negative_eigenvalues = -1;
  bool stable = false;
  double lowest_eigenvalue = std::numeric_limits<double>::quiet_NaN();
};

struct StaticEvent {
  cont::EventType type = cont::EventType::kLimitPoint;
  StepResult at;  // iterations = 0
  // Stability changes only (else kNone, -1, empty): the classification, the negative counts
  // before and after, the node states at the event and the critical mode's translations per
  // node (rows = nodes; unit largest entry, sign arbitrary).
  cont::Criticality criticality = cont::Criticality::kNone;
  int negative_before = -1;
  int negative_after = -1;
  std::vector<NodeState> states;
  Eigen::MatrixXd mode;
};

struct StaticResult {
  std::vector<StepResult> steps;  // the start point (lambda = 0) is not one
  std::vector<StaticEvent> events;
  std::vector<NodeState> state;  // at the last step (the reference state if there is none)
  // Why the run ended before its end (natural: lambda = 1; pseudo_arclength: load_factor_max),
  // naming the last converged load factor and the reason; empty if it completed or the
  // callback stopped it.
  std::string failure;
};

// Called after each converged (sub)step with the result and the converged state. Returning
// false stops the analysis (no failure).
using StepCallback = std::function<bool(const StepResult&, const std::vector<NodeState>&)>;

// Runs from the reference state at lambda = 0. Keeps no reference. Throws an input error for
// invalid settings or loads; a numerical failure is StaticResult::failure.
StaticResult run_static(const Mesh& mesh, const DofMap& dofs, const ShellElement& element,
                        const ShellLaw& law, Kinematics kinematics, const Loads& loads,
                        const StaticSettings& settings, const StepCallback& callback = {},
                        int threads = 0);

}  // namespace si
