#include "indentation/nodal_gaps.hpp"

namespace si {
namespace {

// A gap this large stands for "beside the indenter's path": phi then pins lambda to zero.
constexpr double kFarGap = 1e6;  // mm

}  // namespace

void NodalGaps::set_fbar(const Vector6d& fbar_top, double offset) {
  thickening_ = std::make_unique<FaceThickening>(shell(), fbar_top, offset);
}

NodeGap NodalGaps::gap(int i, const TermPoint& p, double depth, bool derivative) const {
  const int n = candidates_[i];
  const double travel = body().first_touch() + depth;
  NodeGap g = shell().gap(body().indenter(), body().direction(), body().geometry(n), n, p.states,
                          travel, touch_guess_[i], derivative);
  if (g.hits) {
    touch_guess_[i] = g.touch_travel;
    if (thickening_) g.gap += rise_factor(i, g) * row_dot(rise_rows_[i], p.z.head(shell().size()));
  } else {
    g.gap = kFarGap;
  }
  return g;
}

double NodalGaps::rise_factor(int i, const NodeGap& g) const {
  if (!thickening_ || !g.hits) return 0.0;
  return g.gradient.head<3>().dot(thickening_->director(candidates_[i]));
}

double NodalGaps::gap_value(int i, const TermPoint& p, double depth) const {
  return gap(i, p, depth, false).gap;
}

bool NodalGaps::hits(int i, const TermPoint& p, double depth) const {
  return gap(i, p, depth, false).hits;
}

void NodalGaps::gradient(int i, const TermPoint& p,
                         std::vector<std::pair<int, double>>& out) const {
  const NodeGap g = gap(i, p, face_depth(candidates_[i], p.z, p.h), false);
  for (int l = 0; l < 5; ++l)
    if (slots_[i].eq[l] >= 0) out.emplace_back(slots_[i].eq[l], g.gradient[l]);
  const double k = rise_factor(i, g);
  if (k != 0.0)
    for (const auto& [eq, value] : rise_rows_[i]) out.emplace_back(eq, k * value);
}

double NodalGaps::pressure_area(int i) const {
  return shell().tributary_area(candidates_[i]);
}

void NodalGaps::candidates_changed(bool appended) {
  // Appended candidates keep the guesses (and rise rows) of the old ones.
  if (!appended) {
    touch_guess_.clear();
    rise_rows_.clear();
  }
  touch_guess_.resize(candidates_.size(), body().first_touch());
  if (thickening_)
    for (std::size_t i = rise_rows_.size(); i < candidates_.size(); ++i)
      rise_rows_.push_back(thickening_->rise_row(candidates_[i]));
}

void NodalGaps::reset_caches() {
  touch_guess_.assign(candidates_.size(), body().first_touch());
}

void NodalGaps::add_pattern(Triplets& t) const {
  ContactRows::add_pattern(t);
  for (int i = 0; i < static_cast<int>(rise_rows_.size()); ++i)
    for (const auto& [eq, value] : rise_rows_[i]) {
      t.emplace_back(first() + i, eq, 0.0);
      t.emplace_back(eq, first() + i, 0.0);
    }
}

void NodalGaps::locate(const SparseMatrix& J) {
  ContactRows::locate(J);
  rise_slots_.assign(rise_rows_.size(), {});
  for (int i = 0; i < static_cast<int>(rise_rows_.size()); ++i)
    for (const auto& [eq, value] : rise_rows_[i])
      rise_slots_[i].emplace_back(value_slot(J, first() + i, eq), value_slot(J, eq, first() + i));
}

// r_free -= sum_i lambda_i G_i: the contact force lambda_i a and its moment on node i, and with
// the F-bar term lambda_i (a . n) c_i on the node's elements (the paper's F_e t, eq 16).
void NodalGaps::add_shell_force(const TermPoint& p, cont::Vector& r_free) {
  for (int i = 0; i < size(); ++i) {
    const double lambda = p.z[first() + i];
    if (lambda == 0.0) continue;
    const NodeGap g = gap(i, p, face_depth(candidates_[i], p.z, p.h), false);
    add_node_row_force(slots_[i], g, lambda, r_free);
    const double k = rise_factor(i, g);
    if (k != 0.0)
      for (const auto& [eq, value] : rise_rows_[i]) r_free[eq] -= lambda * k * value;
  }
}

void NodalGaps::add_jacobian(const TermPoint& p, double* J,
                             std::vector<ContactJacobianRow>* condensed) {
  prepare_layer(p);
  const bool nonlinear = shell().nonlinear();
  Eigen::VectorXd row_b(size());
  for (int i = 0; i < size(); ++i) {
    const double lambda = p.z[first() + i];
    const DentValue dent = dent_at(candidates_[i], p.z);
    const NodeGap g = gap(i, p, p.h - dent.u, nonlinear && lambda != 0.0);
    const NcpValue phi = complementarity(lambda, g.gap + layer_at(i, p));
    const Slots& s = slots_[i];
    const double b = phi.d_b * kappa();
    if (condensed) condensed->push_back(condensed_node_row(s, g, multiplier_diagonal(i, phi), b));
    add_node_row_entries(s, g, lambda, b, nonlinear && lambda != 0.0, J);
    add_multiplier_terms(i, phi, g.hits ? dent.rate : 0.0, J);
    row_b[i] = b;
    const double k = rise_factor(i, g);
    if (k == 0.0) continue;
    for (std::size_t j = 0; j < rise_rows_[i].size(); ++j) {
      const double c = k * rise_rows_[i][j].second;
      J[rise_slots_[i][j].first] += b * c;
      J[rise_slots_[i][j].second] -= c;
    }
  }
  set_layer_coupling(row_b);
}

SparseMatrix NodalGaps::gap_matrix(const TermPoint& reference) const {
  Triplets t;
  for (int i = 0; i < size(); ++i) {
    const NodeGap g = gap(i, reference, 0.0, false);
    if (!g.hits) continue;
    for (int l = 0; l < 5; ++l)
      if (slots_[i].eq[l] >= 0) t.emplace_back(i, slots_[i].eq[l], g.gradient[l]);
    const double k = rise_factor(i, g);
    if (k != 0.0)
      for (const auto& [eq, value] : rise_rows_[i]) t.emplace_back(i, eq, k * value);
  }
  SparseMatrix C(size(), shell().size());
  C.setFromTriplets(t.begin(), t.end());
  return C;
}

}  // namespace si
