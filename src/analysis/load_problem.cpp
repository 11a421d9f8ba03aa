#include "analysis/load_problem.hpp"

#include "core/error.hpp"

namespace si {

LoadProblem::LoadProblem(const Mesh& mesh, const std::vector<Support>& supports,
                         const ShellElement& element, const ShellLaw& law, const Loads& loads,
                         LoadProblemOptions options)
    : options_(std::move(options)),
      dofs_(make_dof_map(mesh, supports)),
      assembler_(mesh, dofs_, element, law, Kinematics::kNonlinear, options_.threads),
      chart_(mesh, dofs_),
      shell_(assembler_, chart_),
      solver_(make_linear_solver(options_.linear_solver)) {
  validate(mesh, loads);
  SI_REQUIRE(!loads.has_follower(), "LoadProblem: follower pressures are not supported");
  load_ = dofs_.restrict_to_free(fixed_load_vector(mesh, loads));
  for (const DisplacementMonitor& m : options_.displacements) {
    const auto it = mesh.node_sets.find(m.node_set);
    if (it == mesh.node_sets.end() || it->second.empty())
      throw_input("LoadProblem: monitor " + m.name + ": no node set \"" + m.node_set + "\"");
    monitor_nodes_.push_back(it->second);
  }
}

LoadProblem::~LoadProblem() = default;

int LoadProblem::size() const {
  return chart_.size();
}

std::vector<NodeState> LoadProblem::node_states(const cont::Vector& x) const {
  std::vector<NodeState> s;
  chart_.states(x, 1.0, s);
  return s;
}

bool LoadProblem::residual(const cont::Vector& x, double lambda, cont::Vector& F) {
  try {
    F = dofs_.restrict_to_free(shell_.at(x).internal_force);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    return false;
  }
  F -= lambda * load_;
  return F.allFinite();
}

bool LoadProblem::factorize(const cont::Vector& x, double lambda) {
  try {
    const Assembly& a = shell_.at(x);
    const cont::Vector r = dofs_.restrict_to_free(a.internal_force) - lambda * load_;
    jacobian_ = a.tangent;
    chart_.to_chart_jacobian(x, r, jacobian_);
    solver_->factorize(jacobian_);  // the first factorization analyses the pattern
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    return false;
  }
  return true;
}

bool LoadProblem::solve(cont::Vector& b) {
  b = solver_->solve(b);
  return b.allFinite();
}

bool LoadProblem::residual_p(const cont::Vector&, double, cont::Vector& out) {
  out = -load_;
  return true;
}

double LoadProblem::inner(const cont::Vector& a, const cont::Vector& b) const {
  return a.dot(b) / static_cast<double>(a.size());
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
  const std::vector<NodeState> s = node_states(x);
  for (std::size_t i = 0; i < monitor_nodes_.size(); ++i) {
    const Vector3d e = options_.displacements[i].direction.normalized();
    double sum = 0;
    for (int n : monitor_nodes_[i]) sum += s[n].u.dot(e);
    m[static_cast<Eigen::Index>(i) + 1] = sum / static_cast<double>(monitor_nodes_[i].size());
  }
  return m;
}

}  // namespace si
