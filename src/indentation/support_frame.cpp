#include "indentation/support_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace si {

SupportFrame::SupportFrame(SupportFrameSetting setting) : setting_(std::move(setting)) {
  const Mesh& mesh = setting_.shell.model().mesh;
  if (setting_.nodes.empty())
    throw_input("no node of the plate lies over the support frame", Where{"", "fixture", "", 0});
  normal_ = mesh.directors[setting_.nodes.front()];
  // A node whose translation along n is held (a clamp) is no candidate: its gap cannot open or
  // close to first order (its row's gradient on the free dofs is zero, a singular row where
  // active), and the clamp's reaction is its support.
  const DofMap& dofs = setting_.shell.dofs();
  std::vector<int> free_nodes;
  for (int n : setting_.nodes) {
    double free = 0;
    for (int l = 0; l < 3; ++l)
      if (dofs.equation(DofMap::dof(n, l)) >= 0) free += normal_[l] * normal_[l];
    if (free > 1e-12) free_nodes.push_back(n);
  }
  setting_.nodes = std::move(free_nodes);
  for (int n : setting_.nodes) {
    if ((mesh.directors[n] - normal_).norm() > 1e-8)
      throw_input(
          "the support frame needs a flat plate over it (the directors of the nodes over "
          "the frame differ)",
          Where{"", "fixture", "", 0});
    const NodeContactGeometry g{mesh.nodes[n], setting_.face_offset};
    geometry_.push_back(g);
    // Flush with the undeformed back face: every gap is zero at the start.
    level_.push_back(normal_.dot(g.X + g.offset * mesh.directors[n]));
  }
}

void SupportFrame::add_pattern(Triplets& t) const {
  for (int i = 0; i < size(); ++i)
    add_node_row_pattern(setting_.shell.dofs(), setting_.nodes[i], first() + i, -1, t);
}

void SupportFrame::locate(const SparseMatrix& J) {
  slots_.clear();
  for (int i = 0; i < size(); ++i)
    slots_.push_back(locate_node_row(setting_.shell.dofs(), setting_.nodes[i], first() + i, -1, J));
}

NodeGap SupportFrame::gap(int i, const TermPoint& p, bool derivative) const {
  return setting_.shell.plane_gap(normal_, level_[i], geometry_[i], setting_.nodes[i], p.states,
                                  derivative);
}

void SupportFrame::add_shell_force(const TermPoint& p, cont::Vector& r_free) {
  for (int i = 0; i < size(); ++i) {
    const double mu = p.z[first() + i];
    if (mu == 0.0) continue;
    add_node_row_force(slots_[i], gap(i, p, false), mu, r_free);
  }
}

void SupportFrame::residual(const TermPoint& p, cont::Vector& F) {
  for (int i = 0; i < size(); ++i)
    F[first() + i] =
        ncp(setting_.ncp, p.z[first() + i], setting_.kappa * gap(i, p, false).gap).value;
}

void SupportFrame::add_jacobian(const TermPoint& p, double* J,
                                std::vector<ContactJacobianRow>* condensed) {
  const bool nonlinear = setting_.shell.nonlinear();
  for (int i = 0; i < size(); ++i) {
    const double mu = p.z[first() + i];
    const bool derivative = nonlinear && mu != 0.0;
    const NodeGap g = gap(i, p, derivative);
    const NcpValue phi = ncp(setting_.ncp, mu, setting_.kappa * g.gap);
    const double b = phi.d_b * setting_.kappa;
    if (condensed) condensed->push_back(condensed_node_row(slots_[i], g, phi.d_a, b));
    add_node_row_entries(slots_[i], g, mu, b, derivative, J);
    J[slots_[i].diagonal] += phi.d_a;
  }
}

void SupportFrame::signature(const TermPoint& p, std::vector<int>& out) const {
  for (int i = 0; i < size(); ++i)
    out.push_back(p.z[first() + i] > setting_.kappa * gap(i, p, false).gap);
}

void SupportFrame::active_gradients(const TermPoint& p, Triplets& out,
                                    std::vector<int>& multiplier_index) const {
  const Eigen::Ref<const cont::Vector> mu = unknowns(p.z);
  const double mu_max = size() ? mu.cwiseAbs().maxCoeff() : 0.0;
  for (int i = 0; i < size(); ++i) {
    if (!(mu[i] > setting_.kappa * gap(i, p, false).gap) || !bears(mu[i], mu_max)) continue;
    const NodeGap g = gap(i, p, false);
    const int row = static_cast<int>(multiplier_index.size());
    for (int l = 0; l < 5; ++l)
      if (slots_[i].eq[l] >= 0) out.emplace_back(row, slots_[i].eq[l], g.gradient[l]);
    multiplier_index.push_back(first() + i);
  }
}

void SupportFrame::quantities(const TermPoint& p, IndentationState& out) const {
  const Eigen::Ref<const cont::Vector> mu = unknowns(p.z);
  const double mu_max = size() ? mu.cwiseAbs().maxCoeff() : 0.0;
  out.frame_force = setting_.shell.model().symmetry_factor * mu.sum();
  out.frame_contact_nodes = 0;
  for (int i = 0; i < size(); ++i) out.frame_contact_nodes += bears(mu[i], mu_max);
}

void SupportFrame::outputs(const TermPoint& p, IndentationState& out) const {
  for (int i = 0; i < size(); ++i) {
    out.frame_nodes.push_back(setting_.nodes[i]);
    out.frame_multipliers.push_back(p.z[first() + i]);
    out.frame_gaps.push_back(gap(i, p, false).gap);
  }
}

}  // namespace si
