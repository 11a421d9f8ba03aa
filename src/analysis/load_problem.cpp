#include "analysis/load_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace si {

LoadProblem::LoadProblem(const Mesh& mesh, DofMap dofs, const ShellElement& element,
                         const ShellLaw& law, const Loads& loads, LoadProblemOptions options)
    : mesh_(mesh),
      loads_(loads),
      options_(std::move(options)),
      dofs_(std::move(dofs)),
      assembler_(mesh, dofs_, element, law, options_.kinematics, options_.threads),
      chart_(mesh, dofs_),
      shell_(assembler_, chart_) {
  validate(mesh, loads_);
  const bool symmetric = !nonlinear();
  if (!symmetric && options_.linear_solver == LinearSolverKind::kCholmod)
    throw_input(
        "the Jacobian of a nonlinear load-controlled run is unsymmetric: cholmod cannot "
        "factor it (use umfpack or klu)");
  solver_ = make_linear_solver(options_.linear_solver);
  fixed_load_ = fixed_load_vector(mesh, loads_);
  // Linear kinematics: a follower pressure acts at the reference positions, as a dead one.
  if (symmetric && loads_.has_follower())
    fixed_load_ += follower_load_vector(mesh, loads_, reference_state(mesh));
  load_ = dofs_.restrict_to_free(fixed_load_);
  if (!symmetric && loads_.has_follower())
    load_ += dofs_.restrict_to_free(follower_load_vector(mesh, loads_, reference_state(mesh)));
  double scale = load_.size() > 0 ? load_.cwiseAbs().maxCoeff() : 0.0;
  scale = std::max(scale, linear_scales());
  force_scale_ = scale > 0 ? scale : 1.0;
  for (const DisplacementMonitor& m : options_.displacements) {
    const auto it = mesh.node_sets.find(m.node_set);
    if (it == mesh.node_sets.end() || it->second.empty())
      throw_input("LoadProblem: monitor " + m.name + ": no node set \"" + m.node_set + "\"");
    monitor_nodes_.push_back(it->second);
  }
}

LoadProblem::LoadProblem(const Mesh& mesh, const std::vector<Support>& supports,
                         const ShellElement& element, const ShellLaw& law, const Loads& loads,
                         LoadProblemOptions options)
    : LoadProblem(mesh, make_dof_map(mesh, supports), element, law, loads, std::move(options)) {}

LoadProblem::~LoadProblem() = default;

// The forces of the prescribed displacements are their reactions, known only at the solution;
// f_int(x = 0, u_p) would overstate them grossly (the whole jump in the first row of elements).
// The linear solution gives their scale: K_ff x = f_ext - K_fp u_p, then the largest internal
// force K [x; u_p] over every dof. K_fp u_p and K [x; u_p] are directional differences at the
// reference, f_int(h x, h u_p) / h, first-order accurate in h (a scale needs no more). The same
// solution sets the roundoff floor of the residual: eps max_i sum_j |K_ij x_j|, the size of the
// terms that cancel in a free row (a stiff membrane under a small load: far above eps |f_ext|).
double LoadProblem::linear_scales() {
  constexpr double h = 1e-7;
  const cont::Vector zero = initial_point();
  jacobian_ = shell_.at(zero, 0.0).tangent;
  const std::unique_ptr<LinearSolver> solver = make_linear_solver(LinearSolverKind::kUmfpack);
  try {
    solver->factorize(jacobian_);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    return 0.0;  // the run reports the singular matrix
  }
  const bool prescribed = has_prescribed_values();
  const cont::Vector k_fp_u =
      prescribed ? cont::Vector(dofs_.restrict_to_free(shell_.force_at(zero, h).internal_force) / h)
                 : cont::Vector::Zero(size());
  const cont::Vector x = solver->solve(load_ - k_fp_u);
  if (!x.allFinite()) return 0.0;
  Eigen::VectorXd terms = Eigen::VectorXd::Zero(x.size());
  for (int c = 0; c < jacobian_.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(jacobian_, c); it; ++it)
      if (it.row() < terms.size() && it.col() < x.size())
        terms[it.row()] += std::abs(it.value() * x[it.col()]);
  if (terms.size() > 0)
    roundoff_force_ = std::numeric_limits<double>::epsilon() *
                      std::max(terms.maxCoeff(), k_fp_u.cwiseAbs().maxCoeff());
  if (!nonlinear()) roundoff_force_ = std::max(roundoff_force_, linear_residual(*solver));
  if (!prescribed) return 0.0;
  const Eigen::VectorXd f = shell_.force_at(h * x, h).internal_force / h;
  return f.size() > 0 && f.allFinite() ? f.cwiseAbs().maxCoeff() : 0.0;
}

// Linear kinematics: the residual of the linear solution at load factor 1, F(x_1, 1) with
// x_1 = -K^-1 F(0, 1) (F is affine in x), computed as the corrector computes it. It is the
// residual's actual floor (the force assembly's and the direct solve's roundoff), which the
// estimate above can miss by orders of magnitude (the pinched cylinder 32x32: 1e4 times): no
// Newton iteration can go below it, and the predictor, the linear solution, is accepted there
// (one solve per load level, as a linear analysis is). 0 if it cannot be evaluated.
double LoadProblem::linear_residual(LinearSolver& solver) {
  cont::Vector f0, f1;
  if (!residual(initial_point(), 1.0, f0)) return 0.0;
  const cont::Vector x = -solver.solve(f0);
  if (!x.allFinite() || !residual(x, 1.0, f1)) return 0.0;
  return f1.size() > 0 ? f1.cwiseAbs().maxCoeff() : 0.0;
}

int LoadProblem::size() const {
  return chart_.size();
}

bool LoadProblem::has_prescribed_values() const {
  for (int dof : dofs_.prescribed_dofs())
    if (dofs_.prescribed_value(dof) != 0.0) return true;
  return false;
}

std::vector<NodeState> LoadProblem::node_states(const cont::Vector& x, double lambda) const {
  std::vector<NodeState> s;
  chart_.states(x, lambda, s);
  return s;
}

Eigen::VectorXd LoadProblem::external_force(double lambda) const {
  Eigen::VectorXd f = lambda * fixed_load_;
  if (nonlinear() && loads_.has_follower())
    f += lambda * follower_load_vector(mesh_, loads_, shell_.states());
  return f;
}

// Linear kinematics: the force of the linear mode at the states that read back x exactly; its
// tangent is the constant K (factorize()).
const Assembly& LoadProblem::assembly_at(const cont::Vector& x, double lambda, bool tangent) {
  return nonlinear() && tangent ? shell_.at(x, lambda) : shell_.force_at(x, lambda);
}

bool LoadProblem::residual(const cont::Vector& x, double lambda, cont::Vector& F) {
  try {
    const Assembly& a = assembly_at(x, lambda, true);
    F = dofs_.restrict_to_free(a.internal_force - external_force(lambda));
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    last_error_ = e.reason();
    return false;
  }
  if (!F.allFinite()) last_error_ = "the residual is not finite";
  return F.allFinite();
}

// Factors the Jacobian, falling back from CHOLMOD to UMFPACK once if it is not positive
// definite; a singular matrix fails in UMFPACK too.
void LoadProblem::factorize_matrix() {
  try {
    solver_->factorize(jacobian_);  // the first factorization analyses the pattern
  } catch (const Error&) {
    if (!solver_->needs_spd()) throw;
    solver_ = make_linear_solver(LinearSolverKind::kUmfpack);
    solver_->factorize(jacobian_);
  }
}

SparseMatrix LoadProblem::chart_jacobian(const cont::Vector& x, double lambda,
                                         std::vector<ShellChart::RotationBlock>& rotations) {
  const Assembly& a = shell_.at(x, lambda);
  // The chart's drilling term differentiates rotation rows that are components of a vector on
  // the current axes: the internal moments. The loads' rotation rows are constant generalised
  // forces (NodalMoment, loads.hpp) with zero derivative; including them (r = f_int - f_ext)
  // was wrong by drill * M per loaded node, which stalled Newton on the rolled-up strip.
  const cont::Vector r = dofs_.restrict_to_free(a.internal_force);
  SparseMatrix J = a.tangent;
  if (loads_.has_follower())
    for_each_follower_stiffness(mesh_, loads_, shell_.states(), [&](int e, const auto& block) {
      assembler_.add_element_block(e, block, -lambda, J);
    });
  rotations = chart_.to_chart_jacobian(x, r, J);
  return J;
}

bool LoadProblem::factorize(const cont::Vector& x, double lambda) {
  factored_x_.resize(0);
  try {
    if (!nonlinear()) {
      if (!factorized_) {
        jacobian_ = shell_.at(initial_point(), 0.0).tangent;
        factorize_matrix();
        factorized_ = true;
      }
      return true;
    }
    jacobian_ = chart_jacobian(x, lambda, rotations_);
    factorize_matrix();
    factored_x_ = x;
    factored_lambda_ = lambda;
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    last_error_ = e.reason();
    return false;
  }
  return true;
}

bool LoadProblem::solve(cont::Vector& b) {
  b = solver_->solve(b);
  return b.allFinite();
}

bool LoadProblem::residual_p(const cont::Vector& x, double lambda, cont::Vector& out) {
  if (has_prescribed_values()) return cont::Problem::residual_p(x, lambda, out);
  if (!nonlinear() || !loads_.has_follower()) {
    out = -load_;
    return true;
  }
  try {
    assembly_at(x, lambda, false);  // the states at x (usually cached)
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    last_error_ = e.reason();
    return false;
  }
  out = -dofs_.restrict_to_free(external_force(1.0));
  return out.allFinite();
}

double LoadProblem::inner(const cont::Vector& a, const cont::Vector& b) const {
  return a.dot(b) / static_cast<double>(a.size());
}

// pi/2: T(x) is well conditioned there (it loses rank only at pi), and a node may turn by
// almost pi/2 more within the next step before the chart becomes singular.
bool LoadProblem::adapt(cont::Vector& x, double /*lambda*/) {
  if (!nonlinear() || chart_.rebase(x, M_PI / 2) == 0) return false;
  shell_.forget();
  ++rebasings_;
  return true;
}

std::vector<std::string> LoadProblem::monitor_names() const {
  std::vector<std::string> names{"load_factor"};
  for (const DisplacementMonitor& m : options_.displacements) names.push_back(m.name);
  return names;
}

// No assembly: the continuation evaluates monitors off the branch too.
cont::Vector LoadProblem::monitors(const cont::Vector& x, double lambda) {
  cont::Vector m(1 + monitor_nodes_.size());
  m[0] = lambda;
  if (monitor_nodes_.empty()) return m;
  const std::vector<NodeState> s = node_states(x, lambda);
  for (std::size_t i = 0; i < monitor_nodes_.size(); ++i) {
    const Vector3d e = options_.displacements[i].direction.normalized();
    double sum = 0;
    for (int n : monitor_nodes_[i]) sum += s[n].u.dot(e);
    m[static_cast<Eigen::Index>(i) + 1] = sum / static_cast<double>(monitor_nodes_[i].size());
  }
  return m;
}

LoadPointState LoadProblem::point_state(const cont::Vector& x, double lambda) {
  const Assembly& a = shell_.force_at(x, lambda);
  return {shell_.states(), a.internal_force, external_force(lambda), a.energy};
}

LoadPointState LoadProblem::point_state_with_base(const std::vector<NodeState>& base,
                                                  const cont::Vector& x, double lambda) {
  std::vector<NodeState> current = chart_.base();
  chart_.set_base(base);
  shell_.forget();
  LoadPointState s;
  try {
    s = point_state(x, lambda);
  } catch (...) {
    chart_.set_base(std::move(current));
    shell_.forget();
    throw;
  }
  chart_.set_base(std::move(current));
  shell_.forget();
  return s;
}

}  // namespace si
