#include "analysis/static_solver.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "core/error.hpp"

namespace si {
namespace {

// A residual this many times the reference force means Newton is diverging.
constexpr double kDivergedResidual = 1e8;

std::string factor_text(double lambda) {
  std::ostringstream os;
  os.precision(10);
  os << lambda;
  return os.str();
}

}  // namespace

void StaticSettings::validate() const {
  const auto bad = [](const std::string& key, const std::string& value, const std::string& why) {
    throw_input(why, Where{"", "static." + key, value, 0});
  };
  if (steps < 1) bad("steps", std::to_string(steps), "need at least 1 load step");
  if (max_iterations < 1)
    bad("max_iterations", std::to_string(max_iterations), "need at least 1 Newton iteration");
  if (!(tolerance > 0 && tolerance < 1))
    bad("tolerance", std::to_string(tolerance), "tolerance must be in (0, 1)");
  if (max_halvings < 0 || max_halvings > 30)
    bad("max_halvings", std::to_string(max_halvings), "max_halvings must be in 0..30");
  if (linear_solver != LinearSolverKind::kCholmod && linear_solver != LinearSolverKind::kUmfpack)
    bad("linear_solver", make_linear_solver(linear_solver)->name(),
        "not a solver for the static run (expected cholmod or umfpack)");
}

StaticSolver::StaticSolver(const Mesh& mesh, const DofMap& dofs, const ShellElement& element,
                           ShellLaw law, Kinematics kinematics, Loads loads,
                           StaticSettings settings, int threads)
    : mesh_(mesh),
      dofs_(dofs),
      loads_(std::move(loads)),
      settings_(std::move(settings)),
      assembler_(mesh, dofs, element, std::move(law), kinematics, threads),
      assembly_(assembler_.make_assembly()) {
  settings_.validate();
  for (int n : settings_.record_nodes)
    if (n < 0 || n >= mesh.num_nodes())
      throw_input("recorded node " + std::to_string(n) + " is not in the mesh",
                  Where{"", "static.record_nodes", std::to_string(n), 0});
  fixed_load_ = fixed_load_vector(mesh, loads_);  // validates the loads
  // Non-symmetric tangent: CHOLMOD would silently use its lower triangle only.
  solver_ = make_linear_solver(loads_.has_follower() ? LinearSolverKind::kUmfpack
                                                     : settings_.linear_solver);
}

StaticSolver::~StaticSolver() = default;

const std::vector<StepResult>& StaticSolver::solve(std::vector<NodeState>& state,
                                                   const StepCallback& callback) {
  SI_REQUIRE(static_cast<int>(state.size()) == mesh_.num_nodes(),
             "static solver needs one nodal state per node");
  steps_.clear();
  if (assembler_.kinematics() == Kinematics::kLinear) {
    solve_linear(state, callback);
  } else {
    solve_nonlinear(state, callback);
  }
  return steps_;
}

void StaticSolver::set_prescribed(std::vector<NodeState>& state, double lambda) const {
  for (int dof : dofs_.prescribed_dofs()) {
    const int local = dof % kShellNodeDofs;
    if (local < 3) state[dof / kShellNodeDofs].u[local] = lambda * dofs_.prescribed_value(dof);
  }
}

Eigen::VectorXd StaticSolver::external_force(const std::vector<NodeState>& state,
                                             double lambda) const {
  Eigen::VectorXd f = lambda * fixed_load_;
  if (loads_.has_follower()) f += lambda * follower_load_vector(mesh_, loads_, state);
  return f;
}

// Factorizes K with the current solver, falling back from CHOLMOD to UMFPACK once if K is not
// positive definite (e.g. past a limit point; a singular K then fails in UMFPACK too).
void StaticSolver::factorize(const SparseMatrix& K) {
  try {
    solver_->factorize(K);
  } catch (const Error&) {
    if (!solver_->needs_spd()) throw;
    solver_ = make_linear_solver(LinearSolverKind::kUmfpack);
    solver_->factorize(K);
  }
}

void StaticSolver::finish_step(const std::vector<NodeState>& state, double lambda,
                               const Assembly& assembly, const Eigen::VectorXd& f_ext,
                               StepResult& result) const {
  result.load_factor = lambda;
  result.energy = assembly.energy;
  result.linear_solver = solver_->kind();
  const Eigen::VectorXd r = reactions(dofs_, assembly.internal_force, f_ext);
  result.reactions.resize(dofs_.num_prescribed());
  for (int i = 0; i < dofs_.num_prescribed(); ++i)
    result.reactions[i] = r[dofs_.prescribed_dofs()[i]];
  result.reaction_force.setZero();
  result.applied_force.setZero();
  for (int n = 0; n < mesh_.num_nodes(); ++n) {
    result.reaction_force += r.segment<3>(kShellNodeDofs * n);
    result.applied_force += f_ext.segment<3>(kShellNodeDofs * n);
  }
  result.displacements.clear();
  for (int n : settings_.record_nodes) result.displacements.push_back(state[n].u);
}

void StaticSolver::solve_linear(std::vector<NodeState>& state, const StepCallback& callback) {
  const std::vector<NodeState> reference = reference_state(mesh_);
  Assembly& assembly = assembly_;
  assembler_.assemble(reference, ElementRequest{false, true}, assembly);
  factorize(assembly.tangent);
  for (int i = 1; i <= settings_.steps; ++i) {
    const double lambda = double(i) / settings_.steps;
    // Linear: f_int(q_p) with the free dofs at zero, then K_ff q_f = lambda f - f_int(q_p).
    state = reference;
    set_prescribed(state, lambda);
    assembler_.assemble(state, ElementRequest{true, false}, assembly);
    const Eigen::VectorXd f_ext = external_force(state, lambda);
    const Eigen::VectorXd q =
        solver_->solve(dofs_.restrict_to_free(f_ext - assembly.internal_force));
    // Translations add; the rotation dofs (a, b) of a node set its director with ONE
    // rotate_node call from the reference frame, so that the element's linear mode reads back
    // exactly (a, b) (shell_element.hpp). A linearised director D + a V1 x D + b V2 x D would be
    // read as atan(|theta|): f_int, reactions and energy off at third order in the rotations.
    Eigen::MatrixX2d rotation = Eigen::MatrixX2d::Zero(mesh_.num_nodes(), 2);
    for (int eq = 0; eq < dofs_.num_free(); ++eq) {
      const int dof = dofs_.free_dofs()[eq];
      const int node = dof / kShellNodeDofs, local = dof % kShellNodeDofs;
      if (local < 3) {
        state[node].u[local] += q[eq];
      } else {
        rotation(node, local - 3) = q[eq];
      }
    }
    for (int node = 0; node < mesh_.num_nodes(); ++node)
      rotate_node(state[node], rotation(node, 0), rotation(node, 1));
    assembler_.assemble(state, ElementRequest{true, false}, assembly);
    StepResult result;
    result.iterations = 1;
    finish_step(state, lambda, assembly, f_ext, result);
    steps_.push_back(result);
    if (callback && !callback(steps_.back(), state)) return;
  }
}

StaticSolver::Attempt StaticSolver::newton(std::vector<NodeState>& state, double lambda,
                                           StepResult& result) {
  set_prescribed(state, lambda);
  Assembly& assembly = assembly_;
  double energy0 = 0, energy_ratio = 1;
  for (int k = 0;; ++k) {
    try {
      assembler_.assemble(state, ElementRequest{true, true}, assembly);
    } catch (const Error& e) {  // e.g. an element inverted by a too-large step: retry smaller
      if (e.kind() != ErrorKind::kNumerical) throw;
      return {false, e.reason()};
    }
    const Eigen::VectorXd f_ext = external_force(state, lambda);
    const Eigen::VectorXd r = dofs_.restrict_to_free(assembly.internal_force - f_ext);
    const double reference = std::max(f_ext.norm(), assembly.internal_force.norm());
    const double residual = r.norm() / (reference > 0 ? reference : 1.0);
    result.residual_history.push_back(residual);
    if (!std::isfinite(residual)) return {false, "the residual is not finite"};
    if (residual <= settings_.tolerance && (k == 0 || energy_ratio <= settings_.tolerance)) {
      result.iterations = k;
      finish_step(state, lambda, assembly, f_ext, result);
      return {true, ""};
    }
    if (k > 0 && residual > kDivergedResidual * settings_.tolerance &&
        residual > result.residual_history.front() * 1e3)
      return {false, "Newton diverged (relative residual " + factor_text(residual) + ")"};
    if (k == settings_.max_iterations)
      return {false, "no convergence in " + std::to_string(k) +
                         " Newton iterations (relative "
                         "residual " +
                         factor_text(residual) + ")"};
    if (loads_.has_follower())
      for_each_follower_stiffness(mesh_, loads_, state, [&](int e, const auto& block) {
        assembler_.add_element_block(e, block, -lambda, assembly.tangent);
      });
    try {
      factorize(assembly.tangent);
    } catch (const Error& e) {
      // Singular at the start of a step: the converged state itself (missing supports, or a
      // critical point) - smaller steps cannot help. Later, the iterate has wandered: retry.
      if (e.kind() != ErrorKind::kNumerical || k == 0) throw;
      return {false, e.reason()};
    }
    const Eigen::VectorXd q = solver_->solve(-r);
    const double energy = std::abs(q.dot(r));
    if (k == 0) energy0 = energy;
    energy_ratio = energy0 > 0 ? energy / energy0 : 0.0;
    for (int n = 0; n < mesh_.num_nodes(); ++n) {
      Eigen::Matrix<double, kShellNodeDofs, 1> dq;
      for (int l = 0; l < kShellNodeDofs; ++l) {
        const int eq = dofs_.equation(DofMap::dof(n, l));
        dq[l] = eq >= 0 ? q[eq] : 0.0;
      }
      state[n].u += dq.head<3>();
      if (dq[3] != 0.0 || dq[4] != 0.0) rotate_node(state[n], dq[3], dq[4]);
    }
  }
}

void StaticSolver::solve_nonlinear(std::vector<NodeState>& state, const StepCallback& callback) {
  const double nominal = 1.0 / settings_.steps;
  double lambda = 0;
  double increment = nominal;
  int halvings = 0;
  while (lambda < 1.0 - 1e-14) {
    // Never step over a nominal load factor i/steps, so those are always recorded.
    const double next_nominal = (std::floor(lambda / nominal + 1e-9) + 1) * nominal;
    const double target = std::min({1.0, next_nominal, lambda + increment});
    std::vector<NodeState> trial = state;
    StepResult result;
    Attempt attempt;
    try {
      attempt = newton(trial, target, result);
    } catch (const Error& e) {
      if (e.kind() != ErrorKind::kNumerical) throw;
      throw_numerical("static step to load factor " + factor_text(target) +
                      " failed: " + e.reason());
    }
    if (!attempt.converged) {
      if (!settings_.halve_on_failure || halvings == settings_.max_halvings)
        throw_numerical(
            "static step to load factor " + factor_text(target) + " failed: " + attempt.reason +
            (settings_.halve_on_failure ? " after " + std::to_string(halvings) + " step halvings"
                                        : " (step halving is off)") +
            "; last converged load factor " + factor_text(lambda));
      increment *= 0.5;
      ++halvings;
      continue;
    }
    state = std::move(trial);
    lambda = target;
    steps_.push_back(std::move(result));
    if (callback && !callback(steps_.back(), state)) return;
    // Back towards the nominal increment after a success.
    if (halvings > 0) {
      increment = std::min(nominal, 2 * increment);
      --halvings;
    }
  }
}

}  // namespace si
