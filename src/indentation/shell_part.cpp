#include "indentation/shell_part.hpp"

#include "model/recovery_error.hpp"

#include "core/error.hpp"
#include "model/nodal_resultants.hpp"

namespace si {

ShellPart::ShellPart(const ShellModel& model, const Vector3d& direction, int threads)
    : model_(model),
      dofs_(make_dof_map(model.mesh, model.supports)),
      assembler_(model.mesh, dofs_, *model.element, model.law, model.kinematics, threads),
      chart_(model.mesh, dofs_),
      assembly_(assembler_, chart_),
      direction_(direction) {
  SI_REQUIRE(model.displacements.empty(),
             "non-zero prescribed displacements (`supports: type: displacement`) are not part of "
             "an indentation run yet; hold the dofs at 0 or use `shellindent static`");
  const Mesh& mesh = model.mesh;
  const int nn = mesh.num_nodes();
  tributary_area_.assign(nn, 0.0);
  node_elements_.assign(nn, {});
  for (int e = 0; e < mesh.num_elements(); ++e) {
    bool supported = false;
    for (int n : mesh.elements[e]) {
      node_elements_[n].push_back(e);
      for (int l = 0; l < 3; ++l) supported = supported || dofs_.is_prescribed(DofMap::dof(n, l));
    }
    if (supported) support_elements_.push_back(e);
    const double a = element_area(mesh, e) / 4;
    for (int i = 0; i < 4; ++i) tributary_area_[mesh.elements[e][i]] += a;
  }
  reference_tangent_ = assembly_.at(Eigen::VectorXd::Zero(chart_.size())).tangent;
  if (!nonlinear()) build_reaction_row();
}

const std::vector<NodeState>& ShellPart::force(const Eigen::VectorXd& x, Eigen::VectorXd& r_free) {
  if (!nonlinear()) {
    chart_.states(x, 1.0, linear_states_);
    r_free = reference_tangent_ * x;
    return linear_states_;
  }
  r_free = dofs_.restrict_to_free(assembly_.at(x).internal_force);
  return assembly_.states();
}

const SparseMatrix& ShellPart::tangent(const Eigen::VectorXd& x) {
  return nonlinear() ? assembly_.at(x).tangent : reference_tangent_;
}

std::vector<ShellChart::RotationBlock> ShellPart::to_chart(const Eigen::VectorXd& x,
                                                           const Eigen::VectorXd& r_free,
                                                           SparseMatrix& J) const {
  // Linear kinematics: no chart, T = I (no blocks).
  if (!nonlinear()) return {};
  return chart_.to_chart_jacobian(x, r_free, J);
}

std::vector<NodeState> ShellPart::states(const Eigen::VectorXd& x) const {
  std::vector<NodeState> s;
  chart_.states(x, 1.0, s);
  return s;
}

Vector5d ShellPart::chart_coordinates(int node, const std::vector<NodeState>& s) const {
  // The node's chart coordinates (u, theta . V1, theta . V2): the linear mode's dofs.
  const NodeState& ref = chart_.reference(node);
  const Vector3d theta = chart_.rotation_vector(node, s[node].d);
  Vector5d q;
  q << s[node].u, theta.dot(ref.v1), theta.dot(ref.v2);
  return q;
}

NodeGap ShellPart::gap(const Indenter& indenter, const Vector3d& direction,
                       const NodeContactGeometry& geometry, int node,
                       const std::vector<NodeState>& s, double travel, double guess,
                       bool derivative) const {
  if (nonlinear())
    return node_gap(indenter, direction, geometry, s[node], travel, guess, derivative);
  return linearized_node_gap(indenter, direction, geometry, chart_.reference(node),
                             chart_coordinates(node, s), travel);
}

NodeGap ShellPart::plane_gap(const Vector3d& normal, double level,
                             const NodeContactGeometry& geometry, int node,
                             const std::vector<NodeState>& s, bool derivative) const {
  if (nonlinear()) return si::plane_gap(normal, level, geometry, s[node], derivative);
  return linearized_plane_gap(normal, level, geometry, chart_.reference(node),
                              chart_coordinates(node, s));
}

void ShellPart::energy_and_reaction(const Eigen::VectorXd& x, double& energy, double& reaction) {
  const double sym = model_.symmetry_factor;
  if (!nonlinear()) {
    energy = sym * 0.5 * x.dot(reference_tangent_ * x);
    reaction = -sym * reaction_row_.dot(x);
    return;
  }
  // Converged points are where the last residual was assembled: usually cached.
  const Assembly& a = assembly_.force_at(x);
  energy = sym * a.energy;
  Vector3d total = Vector3d::Zero();  // sum of the support reactions (internal force there)
  for (int dof : dofs_.prescribed_dofs())
    if (dof % kShellNodeDofs < 3) total[dof % kShellNodeDofs] += a.internal_force[dof];
  reaction = -sym * total.dot(direction_);
}

Vector3d ShellPart::curvature(const std::vector<NodeState>& s, int node) const {
  return nodal_strain_at(model_.mesh, assembler_, *model_.element, s, node, node_elements_[node])
      .segment<3>(3)
      .transpose();
}

double ShellPart::error_estimate(const std::vector<NodeState>& s) const {
  return recovery_error(model_.mesh, assembler_, *model_.element, model_.law, s).relative();
}

// Linear kinematics: the support reaction along e is linear in x, r_e . x with
// r_e = sum over prescribed translations p of e_l(p) K(p, free); built once from the elements
// that touch a support, so a linear path need not assemble anything per point.
void ShellPart::build_reaction_row() {
  const std::vector<NodeState> s = reference_state(model_.mesh);
  reaction_row_ = Eigen::VectorXd::Zero(chart_.size());
  ElementResponse response;
  for (int e : support_elements_) {
    model_.element->compute(assembler_.geometry(e), assembler_.element_states(s, e), model_.law,
                            model_.kinematics, ElementRequest{false, true}, response);
    const ElementDofs dofs = DofMap::element_dofs(model_.mesh.elements[e]);
    for (int r = 0; r < kShellElementDofs; ++r) {
      const int local = r % kShellNodeDofs;
      if (local >= 3 || !dofs_.is_prescribed(dofs[r])) continue;
      for (int c = 0; c < kShellElementDofs; ++c) {
        const int eq = dofs_.equation(dofs[c]);
        if (eq >= 0) reaction_row_[eq] += direction_[local] * response.tangent(r, c);
      }
    }
  }
}

}  // namespace si
