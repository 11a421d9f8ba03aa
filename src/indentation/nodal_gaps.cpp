#include "indentation/nodal_gaps.hpp"

namespace si {
namespace {

// A gap this large stands for "beside the indenter's path": phi then pins lambda to zero.
constexpr double kFarGap = 1e6;  // mm

}  // namespace

NodeGap NodalGaps::gap(int i, const std::vector<NodeState>& s, double depth,
                       bool derivative) const {
  const int n = candidates_[i];
  const double travel = body().first_touch() + depth;
  NodeGap g = shell().gap(body().indenter(), body().direction(), body().geometry(n), n, s, travel,
                          touch_guess_[i], derivative);
  if (g.hits) {
    touch_guess_[i] = g.touch_travel;
  } else {
    g.gap = kFarGap;
  }
  return g;
}

double NodalGaps::gap_value(int i, const TermPoint& p, double depth) const {
  return gap(i, p.states, depth, false).gap;
}

bool NodalGaps::hits(int i, const TermPoint& p, double depth) const {
  return gap(i, p.states, depth, false).hits;
}

void NodalGaps::gradient(int i, const TermPoint& p,
                         std::vector<std::pair<int, double>>& out) const {
  const NodeGap g = gap(i, p.states, face_depth(candidates_[i], p.z, p.h), false);
  for (int l = 0; l < 5; ++l)
    if (slots_[i].eq[l] >= 0) out.emplace_back(slots_[i].eq[l], g.gradient[l]);
}

double NodalGaps::pressure_area(int i) const {
  return shell().tributary_area(candidates_[i]);
}

void NodalGaps::candidates_changed(bool appended) {
  // Appended candidates keep the guesses of the old ones.
  if (!appended) touch_guess_.clear();
  touch_guess_.resize(candidates_.size(), body().first_touch());
}

void NodalGaps::reset_caches() {
  touch_guess_.assign(candidates_.size(), body().first_touch());
}

// r_free -= sum_i lambda_i G_i: the contact force lambda_i a and its moment on node i.
void NodalGaps::add_shell_force(const TermPoint& p, cont::Vector& r_free) {
  for (int i = 0; i < size(); ++i) {
    const double lambda = p.z[first() + i];
    if (lambda == 0.0) continue;
    add_node_row_force(slots_[i], gap(i, p.states, face_depth(candidates_[i], p.z, p.h), false),
                       lambda, r_free);
  }
}

void NodalGaps::add_jacobian(const TermPoint& p, double* J,
                             std::vector<ContactJacobianRow>* condensed) {
  const bool nonlinear = shell().nonlinear();
  for (int i = 0; i < size(); ++i) {
    const double lambda = p.z[first() + i];
    const DentValue dent = dent_at(candidates_[i], p.z);
    const NodeGap g = gap(i, p.states, p.h - dent.u, nonlinear && lambda != 0.0);
    const NcpValue phi = complementarity(lambda, g.gap + layer_at(candidates_[i], lambda));
    const Slots& s = slots_[i];
    const double b = phi.d_b * kappa();
    if (condensed) condensed->push_back(condensed_node_row(s, g, multiplier_diagonal(i, phi), b));
    add_node_row_entries(s, g, lambda, b, nonlinear && lambda != 0.0, J);
    add_multiplier_terms(i, phi, g.hits ? dent.rate : 0.0, J);
  }
}

SparseMatrix NodalGaps::gap_matrix(const TermPoint& reference) const {
  Triplets t;
  for (int i = 0; i < size(); ++i) {
    const NodeGap g = gap(i, reference.states, 0.0, false);
    for (int l = 0; l < 5; ++l)
      if (slots_[i].eq[l] >= 0 && g.hits) t.emplace_back(i, slots_[i].eq[l], g.gradient[l]);
  }
  SparseMatrix C(size(), shell().size());
  C.setFromTriplets(t.begin(), t.end());
  return C;
}

}  // namespace si
