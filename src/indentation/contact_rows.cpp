#include "indentation/contact_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>

#include <Eigen/Geometry>

#include "contact/travel_gap.hpp"

namespace si {

ContactRows::ContactRows(const ContactRowsSetting& setting) : setting_(setting) {}

void ContactRows::set_candidates(const std::vector<int>& nodes) {
  candidates_ = nodes;
  candidates_changed(false);
}

void ContactRows::add_pattern(Triplets& t) const {
  for (int i = 0; i < size(); ++i)
    add_node_row_pattern(shell().dofs(), candidates_[i], first() + i, approach_->alpha_index(), t);
}

RowCoupling ContactRows::row_coupling() const {
  return coupling_.empty() ? RowCoupling{} : coupling_;
}

void ContactRows::locate(const SparseMatrix& J) {
  slots_.clear();
  for (int i = 0; i < size(); ++i)
    slots_.push_back(
        locate_node_row(shell().dofs(), candidates_[i], first() + i, approach_->alpha_index(), J));
  coupling_.members = approach_->coupling_members(candidates_);
  const std::vector<int>& members = coupling_.members;
  const int m = static_cast<int>(members.size());
  auto C = std::make_shared<Eigen::MatrixXd>(m, m);
  for (int q = 0; q < m; ++q) {
    const Eigen::VectorXd& column = approach_->coupling_column(candidates_, members[q]);
    for (int p = 0; p < m; ++p) (*C)(q, p) = p == q ? 0.0 : column[members[p]];
  }
  coupling_.coefficients = std::move(C);
  coupling_.scale = Eigen::VectorXd::Zero(m);
}

void ContactRows::set_layer_coupling(const Eigen::VectorXd& b) {
  for (int p = 0; p < static_cast<int>(coupling_.members.size()); ++p)
    coupling_.scale[p] = b[coupling_.members[p]];
}

double ContactRows::face_depth(int node, const cont::Vector& z, double h) const {
  return h - approach_->dent(node, z).u;
}

double ContactRows::contact_gap(int i, const TermPoint& p, double depth) const {
  return gap_value(i, p, depth) + layer_at(i, p);
}

// The first-touch node's gap at the start is zero only to the travel's roundoff (s(p) is a
// Newton solve, and the linearised gap recomputes its reference point), and a power law's start
// is regular only at the Fischer-Burmeister kink (0, 0), where d_b > 0 puts the dent's rate into
// the alpha column (local-indentation.md 3); on the lambda side (gap +1.8e-15 mm, measured on a
// linear cap) d_b = 0 and the Jacobian is singular. So with a power law, a gap within roundoff
// of zero takes the derivatives of the touch, phi(lambda, 0): the generalised Jacobian's element
// at the kink a roundoff away. The value, and so the solution, is that of the computed gap.
NcpValue ContactRows::complementarity(double lambda, double gap) const {
  NcpValue phi = ncp(setting_.ncp, lambda, kappa() * gap);
  if (approach_->regularizes_touch() && std::abs(gap) <= body().touch_roundoff()) {
    const NcpValue touch = ncp(setting_.ncp, lambda, 0.0);
    phi.d_a = touch.d_a;
    phi.d_b = touch.d_b;
  }
  return phi;
}

double ContactRows::multiplier_diagonal(int i, const NcpValue& phi) const {
  return phi.d_a + phi.d_b * kappa() * approach_->layer_rate(candidates_[i]);
}

void ContactRows::add_multiplier_terms(int i, const NcpValue& phi, double dent_rate,
                                       double* J) const {
  const Slots& s = slots_[i];
  J[s.diagonal] += multiplier_diagonal(i, phi);
  if (s.alpha_column >= 0) J[s.alpha_column] += phi.d_b * kappa() * dent_rate;
}

void ContactRows::residual(const TermPoint& p, cont::Vector& F) {
  prepare_layer(p);
  for (int i = 0; i < size(); ++i) {
    const double lambda = p.z[first() + i];
    const double depth = face_depth(candidates_[i], p.z, p.h);
    F[first() + i] = complementarity(lambda, contact_gap(i, p, depth)).value;
  }
}

// Only the gaps depend on h, through g = s(p) - t0 - h.
void ContactRows::residual_p(const TermPoint& p, cont::Vector& out) {
  prepare_layer(p);
  for (int i = 0; i < size(); ++i) {
    const double lambda = p.z[first() + i];
    const double depth = face_depth(candidates_[i], p.z, p.h);
    if (!hits(i, p, depth)) continue;
    const NcpValue phi = complementarity(lambda, contact_gap(i, p, depth));
    out[first() + i] = -phi.d_b * kappa();
  }
}

void ContactRows::signature(const TermPoint& p, std::vector<int>& out) const {
  prepare_layer(p);
  for (int i = 0; i < size(); ++i) {
    const double lambda = p.z[first() + i];
    const double depth = face_depth(candidates_[i], p.z, p.h);
    out.push_back(lambda > kappa() * contact_gap(i, p, depth));
  }
}

void ContactRows::active_gradients(const TermPoint& p, Triplets& out,
                                   std::vector<int>& multiplier_index) const {
  // Strongly active: active in the signature and pressing (lambda_i > 0 beyond the roundoff of
  // the largest, as contact_nodes counts them). A weakly active node (lambda_i = 0 = g_i) stays
  // free, which makes positive definiteness a sufficient condition (continuation.md 12).
  std::vector<int> active;
  signature(p, active);
  const cont::Vector lambda = multipliers(p.z);
  const double lambda_max = lambda.size() ? lambda.cwiseAbs().maxCoeff() : 0.0;
  std::vector<std::pair<int, double>> entries;
  for (int i = 0; i < size(); ++i) {
    if (!active[i] || !(lambda[i] > 1e-9 * lambda_max && lambda[i] > 0)) continue;
    entries.clear();
    gradient(i, p, entries);
    const int row = static_cast<int>(multiplier_index.size());
    for (const auto& [column, value] : entries) out.emplace_back(row, column, value);
    multiplier_index.push_back(first() + i);
  }
}

// Each new candidate brings the nodes within kGrowthMargin spacings of it (a spacing: the square
// root of its tributary area, on the face in the reference state): the set then grows once in
// several steps instead of at nearly every one, whether the reach spreads with the travel or
// the shell draws nodes under the indenter's edge. A growth re-lays the Jacobian's pattern
// (with an elastic face its zone block, millions of entries on a fine mesh); extra candidates
// are rows pinned to lambda = 0 while the indenter is far.
void ContactRows::add_margin(std::set<int>& added, const std::vector<bool>& is_candidate) const {
  const std::vector<Vector3d>& x = body().face_points();
  std::vector<std::pair<int, double>> reached;  // node, its margin squared
  Eigen::AlignedBox3d box;  // the reached nodes' box widened by the largest margin
  double widest = 0;
  for (int m : added) {
    const double margin = kGrowthMargin * std::sqrt(shell().tributary_area(m));
    reached.emplace_back(m, margin * margin);
    box.extend(x[m]);
    widest = std::max(widest, margin);
  }
  box.min().array() -= widest;
  box.max().array() += widest;
  for (int n = 0; n < static_cast<int>(x.size()); ++n) {
    if (is_candidate[n] || !box.contains(x[n])) continue;
    for (const auto& [m, margin2] : reached)
      if ((x[n] - x[m]).squaredNorm() <= margin2) {
        added.insert(n);
        break;
      }
  }
}

bool ContactRows::adapt(const TermPoint& p) {
  const bool widened = approach_->adapt(candidates_, multipliers(p.z));
  const int nn = static_cast<int>(body().face_points().size());
  std::vector<bool> is_candidate(nn, false);
  for (int n : candidates_) is_candidate[n] = true;
  // Every node not yet a candidate whose contact point is now within candidate_depth of the
  // indenter (measured as travel along its path): the set follows the deformed shell.
  const double t0 = body().first_touch();
  std::set<int> added;
  for (int n = 0; n < nn; ++n) {
    if (is_candidate[n]) continue;
    const double depth = face_depth(n, p.z, p.h);
    const NodeContactGeometry& g0 = body().geometry(n);
    const Vector3d x = g0.X + p.states[n].u + g0.offset * p.states[n].d;
    const TravelGap g = travel_gap(body().indenter(), body().direction(), x, t0 + depth, false);
    if (g.hits && g.travel - t0 - depth <= setting_.candidate_depth) added.insert(n);
  }
  if (added.empty()) return widened;
  add_margin(added, is_candidate);
  candidates_.insert(candidates_.end(), added.begin(), added.end());
  candidates_changed(true);
  return true;
}

void ContactRows::quantities(const TermPoint& p, IndentationState& out) const {
  const ShellModel& model = shell().model();
  const double sym = model.symmetry_factor;
  const Vector3d& e = body().direction();
  const double lambda_max = multipliers(p.z).cwiseAbs().maxCoeff();
  const Vector3d axis_point = model.mesh.nodes[model.apex_node()];
  out.force = total_force(multipliers(p.z));
  for (int i = 0; i < size(); ++i) {
    const int n = candidates_[i];
    const double lambda = p.z[first() + i];
    if (lambda > 1e-9 * lambda_max && lambda > 0) {
      ++out.contact_nodes;
      out.contact_area += sym * shell().tributary_area(n);
      const Vector3d x = model.mesh.nodes[n] + p.states[n].u - axis_point;
      out.contact_radius = std::max(out.contact_radius, (x - x.dot(e) * e).norm());
    }
  }
}

double ContactRows::total_force(const Eigen::Ref<const Eigen::VectorXd>& multipliers) const {
  double force = 0;
  for (Eigen::Index i = 0; i < multipliers.size(); ++i) force += multipliers[i];
  return force * shell().model().symmetry_factor;
}

void ContactRows::outputs(const TermPoint& p, IndentationState& out) const {
  prepare_layer(p);
  // Curvature extremes over the nodes in contact (as contact_nodes counts them).
  const cont::Vector lambda = multipliers(p.z);
  const double lambda_max = lambda.size() ? lambda.cwiseAbs().maxCoeff() : 0.0;
  bool any = false;
  for (int i = 0; i < size(); ++i) {
    const double l = lambda[i];
    if (!(l > 1e-9 * lambda_max && l > 0)) continue;
    const Vector3d k = shell().curvature(p.states, candidates_[i]);
    out.contact_curvature_min = any ? out.contact_curvature_min.cwiseMin(k) : k;
    out.contact_curvature_max = any ? out.contact_curvature_max.cwiseMax(k) : k;
    any = true;
  }
  if (any && shell().model().symmetry_factor > 1) {
    const double k12 =
        std::max(std::abs(out.contact_curvature_min[1]), std::abs(out.contact_curvature_max[1]));
    out.contact_curvature_min[1] = -k12;
    out.contact_curvature_max[1] = k12;
  }
  // Per candidate: multiplier, gap to the (locally flattened) face, pressure; KKT residuals.
  out.min_gap = std::numeric_limits<double>::infinity();
  out.min_multiplier = std::numeric_limits<double>::infinity();
  for (int i = 0; i < size(); ++i) {
    const int n = candidates_[i];
    const double l = p.z[first() + i];
    const double depth = face_depth(n, p.z, p.h);
    const bool on_path = hits(i, p, depth);
    const double g = contact_gap(i, p, depth);
    out.nodes.push_back(n);
    out.multipliers.push_back(l);
    out.gaps.push_back(on_path ? g : std::numeric_limits<double>::infinity());
    out.pressures.push_back(l / pressure_area(i));
    out.min_multiplier = std::min(out.min_multiplier, l);
    if (on_path) {
      out.min_gap = std::min(out.min_gap, g);
      out.max_complementarity = std::max(out.max_complementarity, std::abs(l * g));
    }
  }
}

Eigen::VectorXd ContactRows::reference_gaps(const TermPoint& reference) const {
  Eigen::VectorXd g0(candidates_.size());
  for (int i = 0; i < size(); ++i) g0[i] = gap_value(i, reference, 0.0);
  return g0;
}

}  // namespace si
