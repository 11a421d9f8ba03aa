#include "analysis/indentation_problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "analysis/nodal_resultants.hpp"
#include "contact/travel_gap.hpp"
#include "core/error.hpp"
#include "model/supports.hpp"

namespace si {

// Value slots in the Jacobian of one candidate's entries (-1 where a dof is prescribed).
struct IndentationProblem::CandidateSlots {
  std::array<int, 5> eq{};      // equations of the node's 5 dofs
  std::array<int, 25> block{};  // (eq[r], eq[c]) at 5 r + c
  std::array<int, 5> column{};  // (eq[r], multiplier)
  std::array<int, 5> row{};     // (multiplier, eq[c])
  int diagonal = -1;            // (multiplier, multiplier)
  int alpha_column = -1;        // (multiplier, alpha), power-law local contact
  int alpha_row = -1;           // (alpha, multiplier)
};

// Interpolated traction (IndentationOptions): the weighted gaps over their weights,
// g = g0 - h + C x, and the Jacobian's value slots of C's entries.
struct IndentationProblem::WeightedGaps {
  Eigen::SparseMatrix<double, Eigen::RowMajor> C;  // C~_i / w_i, candidates x free dofs
  Eigen::VectorXd g0;                              // g~0_i / w_i, mm
  Eigen::VectorXd w;                               // w_i, mm^2
  std::vector<int> column;                         // per entry (i, j): slot of (j, multiplier i)
  std::vector<int> row;                            // per entry (i, j): slot of (multiplier i, j)
};

namespace {

// A gap this large stands for "beside the indenter's path": phi then pins lambda to zero.
constexpr double kFarGap = 1e6;  // mm

int value_slot(const SparseMatrix& J, int row, int col) {
  const int* begin = J.innerIndexPtr() + J.outerIndexPtr()[col];
  const int* end = J.innerIndexPtr() + J.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  SI_REQUIRE(it != end && *it == row, "indentation Jacobian: entry missing from the pattern");
  return static_cast<int>(it - J.innerIndexPtr());
}

}  // namespace

double contact_face_offset(const CaseFile& c) {
  const double top = 0.5 * c.laminate.thickness() - c.laminate.reference_offset;
  return c.contact.surface == ContactSurface::kOuter ? top : -c.laminate.reference_offset;
}

IndentationProblem::IndentationProblem(const ShellModel& model, const Indenter& indenter,
                                       const Vector3d& direction, IndentationOptions options)
    : model_(model),
      indenter_(indenter),
      direction_(direction.normalized()),
      options_(std::move(options)),
      dofs_(make_dof_map(model.mesh, model.supports)),
      assembler_(model.mesh, dofs_, *model.element, model.law, model.kinematics, options_.threads),
      chart_(model.mesh, dofs_),
      shell_(assembler_, chart_) {
  SI_REQUIRE(!options_.interpolated_traction || model.kinematics == Kinematics::kLinear,
             "the interpolated contact traction is defined for linear kinematics only");
  const Mesh& mesh = model.mesh;
  const int nn = mesh.num_nodes();
  geometry_.resize(nn);
  std::vector<Vector3d> points(nn);
  for (int n = 0; n < nn; ++n) {
    geometry_[n] = {mesh.nodes[n], options_.contact_offset};
    points[n] = mesh.nodes[n] + options_.contact_offset * mesh.directors[n];
  }
  double touch = 0;
  try {
    touch = indenter.first_touch(points);
  } catch (const Error&) {
    throw_input("the " + indenter.name() +
                    " indenter never touches the shell along its direction of travel",
                Where{"", "indenter", indenter.name(), 0});
  }
  if (touch < 0)
    throw_input("the " + indenter.name() + " indenter starts inside the shell (it would have " +
                    "touched it " + std::to_string(-touch) + " mm before its start position)",
                Where{"", "indenter", indenter.name(), 0});

  // Exact touch travels of the reachable nodes; t0 = the smallest.
  std::vector<int> reachable;
  std::vector<double> travel;
  for (int n = 0; n < nn; ++n) {
    const TravelGap g = travel_gap(indenter, direction_, points[n], touch, false);
    if (g.hits && g.travel - touch <= options_.candidate_depth) {
      reachable.push_back(n);
      travel.push_back(g.travel);
    }
  }
  SI_REQUIRE(!reachable.empty(), "indentation: no node within reach of the indenter");
  const auto first = std::min_element(travel.begin(), travel.end());
  t0_ = *first;
  double extent = 0;
  for (const Vector3d& p : points) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  touch_roundoff_ = 1e-13 * (1 + std::abs(t0_) + extent);
  if (options_.local.kind == LocalLawKind::kPowerLaw)
    measure_dent_radii(points, reachable[first - travel.begin()]);

  tributary_area_.assign(nn, 0.0);
  neighbours_.assign(nn, {});
  node_elements_.assign(nn, {});
  for (int e = 0; e < mesh.num_elements(); ++e) {
    bool supported = false;
    for (int n : mesh.elements[e]) {
      node_elements_[n].push_back(e);
      for (int l = 0; l < 3; ++l) supported = supported || dofs_.is_prescribed(DofMap::dof(n, l));
    }
    if (supported) support_elements_.push_back(e);
    const double a = element_area(mesh, e) / 4;
    for (int i = 0; i < 4; ++i) {
      const int n = mesh.elements[e][i];
      tributary_area_[n] += a;
      for (int j = 0; j < 4; ++j)
        if (j != i) neighbours_[n].push_back(mesh.elements[e][j]);
    }
  }
  for (auto& v : neighbours_) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  }

  // The reference tangent: kappa, the Jacobian's pattern, and K itself for linear kinematics.
  reference_tangent_ = shell_.at(Eigen::VectorXd::Zero(chart_.size())).tangent;
  const int apex = model.apex_node();
  Matrix3d Ka = Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int ei = dofs_.equation(DofMap::dof(apex, i)),
                ej = dofs_.equation(DofMap::dof(apex, j));
      if (ei >= 0 && ej >= 0) Ka(i, j) = reference_tangent_.coeff(ei, ej);
    }
  kappa_ = direction_.dot(Ka * direction_);
  SI_REQUIRE(kappa_ > 0, "indentation: the apex has no stiffness along the direction of travel");
  if (model.kinematics == Kinematics::kLinear) build_reaction_row();

  choose_candidates(reachable);
}

IndentationProblem::~IndentationProblem() = default;

// r_n of the dent profile: the distance of node n's reference contact point from the indenter's
// axis, measured from the first-touch node's distance r_f as (r_n^2 - r_f^2)^0.5 (0 inside it).
// With a node on the axis (the apex under the default pose) r_f = 0 up to roundoff, which this
// removes; without one (an indenter off the nodes' lines) the first-touch node still counts as
// the patch's centre. Either way the row closed at first touch has d g / d alpha = 1 at
// alpha = 0, which keeps the start's Jacobian regular (local-indentation.md 3). For a sphere
// over a flat face r_n^2 - r_f^2 = 2 R (s(P_n) - t0) to O(r^4/R^2): the shifted radius is the
// one the rigid sphere's own gap profile sees. Reference configuration: Hertz's profile is a
// small-strain field over the undeformed surface, and the face's lateral motion is of the order
// of the half-space's own radial surface displacement, which Hertz's theory neglects.
void IndentationProblem::measure_dent_radii(const std::vector<Vector3d>& points, int first) {
  const Vector3d q = indenter_.pose().position;
  const auto axis_distance = [&](const Vector3d& p) {
    const Vector3d d = p - q;
    return (d - d.dot(direction_) * direction_).norm();
  };
  const double rf = axis_distance(points[first]);
  dent_radius_.resize(points.size());
  for (std::size_t n = 0; n < points.size(); ++n) {
    const double r = axis_distance(points[n]);
    dent_radius_[n] = std::sqrt(std::max(r * r - rf * rf, 0.0));
  }
  dent_radius_[first] = 0;
}

void IndentationProblem::choose_candidates(const std::vector<int>& nodes) {
  candidates_ = nodes;
  touch_guess_.assign(candidates_.size(), t0_);
  if (options_.interpolated_traction) build_weighted_gaps();
  build_pattern();
}

void IndentationProblem::build_weighted_gaps() {
  const InterpolatedContact ic = integrate_interpolated_contact(
      model_.mesh, assembler_, *model_.element,
      ContactFace{indenter_, direction_, options_.contact_offset, t0_}, candidates_,
      options_.interpolated);
  weighted_ = std::make_unique<WeightedGaps>();
  const Eigen::VectorXd inverse = ic.w.cwiseInverse();
  weighted_->C = inverse.asDiagonal() * ic.C;
  weighted_->C.makeCompressed();
  weighted_->g0 = inverse.cwiseProduct(ic.g0);
  weighted_->w = ic.w;
}

void IndentationProblem::restore_candidates(const std::vector<int>& nodes) {
  for (int n : nodes)
    SI_REQUIRE(n >= 0 && n < model_.mesh.num_nodes(), "restore_candidates: node out of range");
  choose_candidates(nodes);
}

void IndentationProblem::build_pattern() {
  const int nf = chart_.size(), nc = static_cast<int>(candidates_.size());
  const SparseMatrix& K = reference_tangent_;  // the shell's pattern
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(K.nonZeros() + 36 * nc);
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) t.emplace_back(it.row(), j, 0.0);
  slots_.assign(nc, {});
  for (int i = 0; i < nc; ++i) {
    const int n = candidates_[i], m = nf + i;
    for (int l = 0; l < 5; ++l) slots_[i].eq[l] = dofs_.equation(DofMap::dof(n, l));
    for (int r : slots_[i].eq) {
      if (r < 0) continue;
      t.emplace_back(r, m, 0.0);
      t.emplace_back(m, r, 0.0);
      for (int c : slots_[i].eq)
        if (c >= 0) t.emplace_back(r, c, 0.0);
    }
    t.emplace_back(m, m, 0.0);
  }
  if (weighted_)
    for (int i = 0; i < nc; ++i)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(weighted_->C, i); it;
           ++it) {
        t.emplace_back(static_cast<int>(it.col()), nf + i, 0.0);
        t.emplace_back(nf + i, static_cast<int>(it.col()), 0.0);
      }
  const UnknownLayout u = layout();
  if (u.local) {
    const int a = u.alpha_index();
    for (int i = 0; i < nc; ++i) {
      t.emplace_back(nf + i, a, 0.0);
      t.emplace_back(a, nf + i, 0.0);
    }
    t.emplace_back(a, a, 0.0);
  }
  jacobian_ = SparseMatrix(u.size(), u.size());
  jacobian_.setFromTriplets(t.begin(), t.end());
  jacobian_.makeCompressed();

  k_to_j_.resize(K.nonZeros());
  for (int j = 0; j < K.outerSize(); ++j)
    for (int k = K.outerIndexPtr()[j]; k < K.outerIndexPtr()[j + 1]; ++k)
      k_to_j_[k] = value_slot(jacobian_, K.innerIndexPtr()[k], j);
  for (int i = 0; i < nc; ++i) {
    CandidateSlots& s = slots_[i];
    const int m = nf + i;
    for (int r = 0; r < 5; ++r) {
      s.column[r] = s.eq[r] >= 0 ? value_slot(jacobian_, s.eq[r], m) : -1;
      s.row[r] = s.eq[r] >= 0 ? value_slot(jacobian_, m, s.eq[r]) : -1;
      for (int c = 0; c < 5; ++c)
        s.block[5 * r + c] =
            s.eq[r] >= 0 && s.eq[c] >= 0 ? value_slot(jacobian_, s.eq[r], s.eq[c]) : -1;
    }
    s.diagonal = value_slot(jacobian_, m, m);
    if (u.local) {
      s.alpha_column = value_slot(jacobian_, m, u.alpha_index());
      s.alpha_row = value_slot(jacobian_, u.alpha_index(), m);
    }
  }
  if (weighted_) {
    weighted_->column.clear();
    weighted_->row.clear();
    for (int i = 0; i < nc; ++i)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(weighted_->C, i); it;
           ++it) {
        weighted_->column.push_back(value_slot(jacobian_, static_cast<int>(it.col()), nf + i));
        weighted_->row.push_back(value_slot(jacobian_, nf + i, static_cast<int>(it.col())));
      }
  }
  alpha_diagonal_ = u.local ? value_slot(jacobian_, u.alpha_index(), u.alpha_index()) : -1;
  // The Krylov solver condenses rows on one node's dofs: not the weighted rows, which span the
  // node's elements (the direct LU then). The local approach alpha, which couples every row,
  // borders the matrix it solves (contact_jacobian_solver.hpp).
  if (options_.linear_solver == kPreconditionedKrylov && !weighted_) {
    if (!krylov_)
      krylov_ =
          std::make_unique<ContactJacobianSolver>(kappa_, "umfpack", options_.krylov_tolerance);
    solver_.reset();
  } else {
    krylov_.reset();
    solver_ = make_linear_solver(
        options_.linear_solver == kPreconditionedKrylov ? "umfpack" : options_.linear_solver);
  }
}

UnknownLayout IndentationProblem::layout() const {
  return {chart_.size(), static_cast<int>(candidates_.size()),
          options_.local.kind == LocalLawKind::kPowerLaw ? 1 : 0};
}

int IndentationProblem::size() const {
  return layout().size();
}

DentValue IndentationProblem::dent(int node, const cont::Vector& z) const {
  const UnknownLayout u = layout();
  if (!u.local) return {};
  // One profile per alpha: every candidate's gap at an iterate shares it.
  const double alpha = z[u.alpha_index()];
  if (!dent_profile_ || dent_profile_->alpha != alpha)
    dent_profile_ = options_.local.dent_profile(alpha);
  return dent_profile_->at(dent_radius_[node]);
}

double IndentationProblem::face_depth(int node, const cont::Vector& z, double h) const {
  return h - dent(node, z).u;
}

double IndentationProblem::layer_approach(int i, double lambda) const {
  if (options_.local.kind != LocalLawKind::kThinLayer) return 0.0;
  return options_.local.compliance * lambda / tributary_area_[candidates_[i]];
}

cont::Vector IndentationProblem::initial_point() const {
  return cont::Vector::Zero(size());
}

std::vector<NodeState> IndentationProblem::node_states(const cont::Vector& z) const {
  SI_REQUIRE(z.size() == size(), "indentation: unknown vector of the wrong size (" +
                                     std::to_string(z.size()) + " for " + std::to_string(size()) +
                                     ")");
  std::vector<NodeState> s;
  chart_.states(z.head(chart_.size()), 1.0, s);
  return s;
}

NodeGap IndentationProblem::gap(int i, const std::vector<NodeState>& s, double h,
                                bool derivative) const {
  const int n = candidates_[i];
  const double travel = t0_ + h;
  NodeGap g;
  if (model_.kinematics == Kinematics::kLinear) {
    // The node's chart coordinates (u, theta . V1, theta . V2): the linear mode's dofs.
    const NodeState& ref = chart_.reference(n);
    const Vector3d theta = chart_.rotation_vector(n, s[n].d);
    Vector5d q;
    q << s[n].u, theta.dot(ref.v1), theta.dot(ref.v2);
    g = linearized_node_gap(indenter_, direction_, geometry_[n], ref, q, travel);
  } else {
    g = node_gap(indenter_, direction_, geometry_[n], s[n], travel, touch_guess_[i], derivative);
  }
  if (g.hits) {
    touch_guess_[i] = g.touch_travel;
  } else {
    g.gap = kFarGap;
  }
  return g;
}

double IndentationProblem::gap_value(int i, const cont::Vector& z, const std::vector<NodeState>& s,
                                     double depth) const {
  if (!weighted_) return gap(i, s, depth, false).gap;
  return weighted_->g0[i] - depth + weighted_->C.row(i).dot(z.head(chart_.size()));
}

// The first-touch node's gap at the start is zero only to the travel's roundoff (s(p) is a
// Newton solve, and the linearised gap recomputes its reference point), and a power law's start
// is regular only at the Fischer-Burmeister kink (0, 0), where d_b > 0 puts the dent's rate into
// the alpha column (local-indentation.md 3); on the lambda side (gap +1.8e-15 mm, measured on a
// linear cap) d_b = 0 and the Jacobian is singular. So with a power law, a gap within roundoff
// of zero takes the derivatives of the touch, phi(lambda, 0): the generalised Jacobian's element
// at the kink a roundoff away. The value, and so the solution, is that of the computed gap.
NcpValue IndentationProblem::complementarity(double lambda, double gap) const {
  NcpValue phi = ncp(options_.ncp, lambda, kappa_ * gap);
  if (options_.local.kind == LocalLawKind::kPowerLaw && std::abs(gap) <= touch_roundoff_) {
    const NcpValue touch = ncp(options_.ncp, lambda, 0.0);
    phi.d_a = touch.d_a;
    phi.d_b = touch.d_b;
  }
  return phi;
}

double IndentationProblem::contact_gap(int i, const cont::Vector& z,
                                       const std::vector<NodeState>& s, double depth,
                                       double lambda) const {
  return gap_value(i, z, s, depth) + layer_approach(i, lambda);
}

// r_free = r(x) - sum lambda_i G_i on the free dofs; returns the node states at z. Nonlinear
// kinematics: the force and tangent at x stay in shell_ for factorize().
const std::vector<NodeState>& IndentationProblem::shell_terms(const cont::Vector& z, double h,
                                                              cont::Vector& r_free) {
  const int nf = chart_.size();
  const cont::Vector x = z.head(nf);
  const bool linear = model_.kinematics == Kinematics::kLinear;
  if (linear) {
    chart_.states(x, 1.0, linear_states_);
    r_free = reference_tangent_ * x;
  } else {
    r_free = dofs_.restrict_to_free(shell_.at(x).internal_force);
  }
  const std::vector<NodeState>& states = linear ? linear_states_ : shell_.states();
  if (weighted_) {
    r_free -= weighted_->C.transpose() * multipliers(z);
    return states;
  }
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const double lambda = z[nf + static_cast<int>(i)];
    if (lambda == 0.0) continue;
    const NodeGap g = gap(static_cast<int>(i), states, face_depth(candidates_[i], z, h), false);
    for (int l = 0; l < 5; ++l)
      if (slots_[i].eq[l] >= 0) r_free[slots_[i].eq[l]] -= lambda * g.gradient[l];
  }
  return states;
}

bool IndentationProblem::residual(const cont::Vector& z, double h, cont::Vector& F) {
  ++counters_.residuals;
  const int nf = chart_.size();
  cont::Vector r;
  const std::vector<NodeState>* states = nullptr;
  try {
    states = &shell_terms(z, h, r);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    return false;
  }
  F.resize(size());
  F.head(nf) = r;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const int c = static_cast<int>(i);
    const double lambda = z[nf + c];
    const double depth = face_depth(candidates_[i], z, h);
    F[nf + c] = complementarity(lambda, contact_gap(c, z, *states, depth, lambda)).value;
  }
  const UnknownLayout u = layout();
  if (u.local) {
    const double alpha = z[u.alpha_index()];
    F[u.alpha_index()] =
        model_.symmetry_factor * multipliers(z).sum() - options_.local.force(alpha);
  }
  return F.allFinite();
}

// d phi_i / d lambda_i: phi_a, plus the thin-layer approach's share through the gap.
double IndentationProblem::multiplier_diagonal(int i, const NcpValue& phi) const {
  return phi.d_a + phi.d_b * kappa_ * layer_approach(i, 1.0);
}

// The Jacobian entries of candidate i's multiplier row and column that are the same for nodal
// and weighted gaps: the diagonal and, with a power-law local contact, the alpha coupling
// (d g / d alpha = the dent's rate where the gap reaches the indenter, `dent_rate`, 0 beside
// it; alpha's row sums the multipliers).
void IndentationProblem::add_multiplier_terms(int i, const NcpValue& phi, double dent_rate,
                                              double* J) const {
  const CandidateSlots& s = slots_[i];
  J[s.diagonal] += multiplier_diagonal(i, phi);
  if (layout().local == 0) return;
  J[s.alpha_column] += phi.d_b * kappa_ * dent_rate;
  J[s.alpha_row] += model_.symmetry_factor;
}

bool IndentationProblem::factorize(const cont::Vector& z, double h) {
  ++counters_.factorizations;
  const int nf = chart_.size();
  cont::Vector r_free;
  const std::vector<NodeState>* states = nullptr;
  try {
    states = &shell_terms(z, h, r_free);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    return false;
  }
  const bool nonlinear = model_.kinematics == Kinematics::kNonlinear;
  const SparseMatrix& K = nonlinear ? shell_.at(z.head(nf)).tangent : reference_tangent_;
  double* J = jacobian_.valuePtr();
  std::fill(J, J + jacobian_.nonZeros(), 0.0);
  for (int k = 0; k < K.nonZeros(); ++k) J[k_to_j_[k]] = K.valuePtr()[k];
  std::vector<ContactJacobianRow> rows(krylov_ ? candidates_.size() : 0);
  const UnknownLayout u = layout();
  for (std::size_t i = 0; weighted_ && i < candidates_.size(); ++i) {
    const int k = static_cast<int>(i);
    const double lambda = z[nf + k];
    const DentValue dent_k = dent(candidates_[i], z);
    const NcpValue phi = complementarity(lambda, contact_gap(k, z, *states, h - dent_k.u, lambda));
    for (int e = weighted_->C.outerIndexPtr()[k]; e < weighted_->C.outerIndexPtr()[k + 1]; ++e) {
      J[weighted_->column[e]] -= weighted_->C.valuePtr()[e];
      J[weighted_->row[e]] += phi.d_b * kappa_ * weighted_->C.valuePtr()[e];
    }
    add_multiplier_terms(k, phi, dent_k.rate, J);  // weighted gaps always reach the indenter
  }
  for (std::size_t i = 0; !weighted_ && i < candidates_.size(); ++i) {
    const int ci = static_cast<int>(i);
    const double lambda = z[nf + ci];
    const DentValue dent_i = dent(candidates_[i], z);
    const NodeGap g = gap(ci, *states, h - dent_i.u, nonlinear && lambda != 0.0);
    const NcpValue phi = complementarity(lambda, g.gap + layer_approach(ci, lambda));
    const CandidateSlots& s = slots_[i];
    if (krylov_) {
      rows[i].eq = s.eq;
      for (int r = 0; r < 5; ++r) rows[i].gradient[r] = g.gradient[r];
      rows[i].a = multiplier_diagonal(ci, phi);
      rows[i].b = phi.d_b * kappa_;
    }
    for (int r = 0; r < 5; ++r) {
      if (s.eq[r] < 0) continue;
      J[s.column[r]] -= g.gradient[r];
      J[s.row[r]] += phi.d_b * kappa_ * g.gradient[r];
      if (nonlinear && lambda != 0.0)
        for (int c = 0; c < 5; ++c)
          if (s.eq[c] >= 0) J[s.block[5 * r + c]] -= lambda * g.gradient_derivative(r, c);
    }
    add_multiplier_terms(ci, phi, g.hits ? dent_i.rate : 0.0, J);
  }
  if (u.local) J[alpha_diagonal_] -= options_.local.stiffness(z[u.alpha_index()]);
  // Linear kinematics: no chart, T = I (no blocks).
  const std::vector<ShellChart::RotationBlock> rotations =
      nonlinear ? chart_.to_chart_jacobian(z.head(nf), r_free, jacobian_)
                : std::vector<ShellChart::RotationBlock>{};
  try {
    if (krylov_)
      krylov_->factorize(jacobian_, nf, rotations, rows, u.local);
    else
      solver_->factorize(jacobian_);  // the first factorization analyses the pattern
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    return false;
  }
  return true;
}

bool IndentationProblem::solve(cont::Vector& b) {
  ++counters_.solves;
  b = krylov_ ? krylov_->solve(b) : solver_->solve(b);
  return b.allFinite();
}

// Only the gaps depend on h, through g = s(p) - t0 - h.
bool IndentationProblem::residual_p(const cont::Vector& z, double h, cont::Vector& out) {
  const int nf = chart_.size();
  std::vector<NodeState> s = node_states(z);
  out = cont::Vector::Zero(size());
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const int c = static_cast<int>(i);
    const double lambda = z[nf + c];
    const double depth = face_depth(candidates_[i], z, h);
    if (!weighted_ && !gap(c, s, depth, false).hits) continue;
    const NcpValue phi = complementarity(lambda, contact_gap(c, z, s, depth, lambda));
    out[nf + c] = -phi.d_b * kappa_;
  }
  return true;
}

double IndentationProblem::force_scale(const cont::Vector& z) const {
  const double force = multipliers(z).sum() * model_.symmetry_factor;
  return std::max(std::abs(force), kappa_ * 1e-3);
}

double IndentationProblem::inner(const cont::Vector& a, const cont::Vector& b) const {
  const int nf = chart_.size(), local = layout().local;
  const Eigen::Index nc = a.size() - nf - local;
  // alpha (mm) counts as one more shell coordinate.
  double shell = (a.head(nf).dot(b.head(nf)) + a.tail(local).dot(b.tail(local))) / nf;
  if (nc > 0) shell += a.tail(nc).dot(b.tail(nc)) / (static_cast<double>(nc) * kappa_ * kappa_);
  return shell;
}

std::vector<std::string> IndentationProblem::monitor_names() const {
  return {"force_N", "apex_w_mm", "contact_radius_mm", "k11_per_mm", "k12_per_mm", "k22_per_mm"};
}

cont::Vector IndentationProblem::monitor_vector(const IndentationState& s) {
  cont::Vector m(6);
  m << s.force, s.apex_deflection, s.contact_radius, s.apex_curvature[0], s.apex_curvature[1],
      s.apex_curvature[2];
  return m;
}

// The monitors need no assembly (the continuation evaluates them off the branch too): the
// force, apex deflection, contact radius and apex curvatures only.
cont::Vector IndentationProblem::monitors(const cont::Vector& z, double h) {
  if (cached_state_ && h == cached_h_ && z.size() == cached_z_.size() && z == cached_z_)
    return monitor_vector(*cached_state_);
  IndentationState out;
  const std::vector<NodeState> s = node_states(z);
  kinematic_quantities(z, s, out);
  return monitor_vector(out);
}

std::vector<int> IndentationProblem::signature(const cont::Vector& z, double h) {
  const int nf = chart_.size();
  const std::vector<NodeState> s = node_states(z);
  std::vector<int> active(candidates_.size());
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const int c = static_cast<int>(i);
    const double lambda = z[nf + c];
    const double depth = face_depth(candidates_[i], z, h);
    active[i] = lambda > kappa_ * contact_gap(c, z, s, depth, lambda);
  }
  return active;
}

bool IndentationProblem::adapt(cont::Vector& z, double h) {
  const std::vector<NodeState> s = node_states(z);
  std::vector<bool> is_candidate(model_.mesh.num_nodes(), false);
  for (int n : candidates_) is_candidate[n] = true;
  // Every node not yet a candidate whose contact point is now within candidate_depth of the
  // indenter (measured as travel along its path): the set follows the deformed shell.
  std::set<int> added;
  for (int n = 0; n < model_.mesh.num_nodes(); ++n) {
    if (is_candidate[n]) continue;
    const double depth = face_depth(n, z, h);
    const Vector3d p = geometry_[n].X + s[n].u + geometry_[n].offset * s[n].d;
    const TravelGap g = travel_gap(indenter_, direction_, p, t0_ + depth, false);
    if (g.hits && g.travel - t0_ - depth <= options_.candidate_depth) added.insert(n);
  }
  if (added.empty()) return false;
  const int nf = chart_.size(), local = layout().local;
  const cont::Vector lambda = multipliers(z);
  const cont::Vector alpha = z.tail(local);
  std::vector<int> nodes = candidates_;
  nodes.insert(nodes.end(), added.begin(), added.end());
  const std::vector<double> guesses = touch_guess_;
  choose_candidates(nodes);
  std::copy(guesses.begin(), guesses.end(), touch_guess_.begin());
  cont::Vector grown = cont::Vector::Zero(size());
  grown.head(nf) = z.head(nf);
  grown.segment(nf, lambda.size()) = lambda;
  grown.tail(local) = alpha;
  z = grown;
  return true;
}

SparseMatrix IndentationProblem::contact_matrix() const {
  SI_REQUIRE(model_.kinematics == Kinematics::kLinear, "contact_matrix: linear kinematics only");
  if (weighted_) return SparseMatrix(weighted_->C);
  const std::vector<NodeState> s = node_states(initial_point());
  std::vector<Eigen::Triplet<double, int>> t;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const NodeGap g = gap(static_cast<int>(i), s, 0.0, false);
    for (int l = 0; l < 5; ++l)
      if (slots_[i].eq[l] >= 0 && g.hits)
        t.emplace_back(static_cast<int>(i), slots_[i].eq[l], g.gradient[l]);
  }
  SparseMatrix C(static_cast<int>(candidates_.size()), chart_.size());
  C.setFromTriplets(t.begin(), t.end());
  return C;
}

Eigen::VectorXd IndentationProblem::reference_gaps() const {
  const std::vector<NodeState> s = node_states(initial_point());
  Eigen::VectorXd g0(candidates_.size());
  for (std::size_t i = 0; i < candidates_.size(); ++i)
    g0[static_cast<Eigen::Index>(i)] = gap_value(static_cast<int>(i), initial_point(), s, 0.0);
  return g0;
}

Eigen::VectorXd IndentationProblem::layer_compliances() const {
  Eigen::VectorXd c(candidates_.size());
  for (std::size_t i = 0; i < candidates_.size(); ++i)
    c[static_cast<Eigen::Index>(i)] = layer_approach(static_cast<int>(i), 1.0);
  return c;
}

// Linear kinematics: the support reaction along e is linear in x, r_e . x with
// r_e = sum over prescribed translations p of e_l(p) K(p, free); built once from the elements
// that touch a support, so a linear path need not assemble anything per point.
void IndentationProblem::build_reaction_row() {
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

// Force, contact nodes, area and radius, apex deflection and curvatures: no assembly, no gaps.
void IndentationProblem::kinematic_quantities(const cont::Vector& z,
                                              const std::vector<NodeState>& s,
                                              IndentationState& out) const {
  const Mesh& mesh = model_.mesh;
  const int nf = chart_.size();
  const double sym = model_.symmetry_factor;
  const int apex = model_.apex_node();
  out.apex_deflection = s[apex].u.dot(direction_);
  out.apex_curvature =
      nodal_strain_at(mesh, assembler_, *model_.element, s, apex, node_elements_[apex])
          .segment<3>(3)
          .transpose();
  const double lambda_max = multipliers(z).cwiseAbs().maxCoeff();
  const Vector3d axis_point = mesh.nodes[apex];
  out.force = 0;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const int n = candidates_[i];
    const double lambda = z[nf + static_cast<int>(i)];
    out.force += lambda;
    if (lambda > 1e-9 * lambda_max && lambda > 0) {
      ++out.contact_nodes;
      out.contact_area += sym * tributary_area_[n];
      const Vector3d p = mesh.nodes[n] + s[n].u - axis_point;
      out.contact_radius =
          std::max(out.contact_radius, (p - p.dot(direction_) * direction_).norm());
    }
  }
  out.force *= sym;
}

// The local approach at the apex and the energy stored in the local compliance (whole shell):
// power law (2/5) k alpha^2.5; thin layer sum_i 1/2 c_L lambda_i^2 / A_i (linear springs).
void IndentationProblem::local_quantities(const cont::Vector& z, IndentationState& out) const {
  const UnknownLayout u = layout();
  if (u.local) {
    out.local_indentation = z[u.alpha_index()];
    out.local_energy = options_.local.energy(z[u.alpha_index()]);
    return;
  }
  if (options_.local.kind != LocalLawKind::kThinLayer) return;
  for (int i = 0; i < u.multipliers; ++i) {
    const double lambda = z[u.lambda_begin() + i];
    out.local_energy += model_.symmetry_factor * 0.5 * lambda * layer_approach(i, lambda);
    if (candidates_[i] == model_.apex_node()) out.local_indentation = layer_approach(i, lambda);
  }
}

void IndentationProblem::contact_curvatures(const cont::Vector& z, const std::vector<NodeState>& s,
                                            IndentationState& out) const {
  const cont::Vector lambda = multipliers(z);
  const double lambda_max = lambda.size() ? lambda.cwiseAbs().maxCoeff() : 0.0;
  bool any = false;
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const double l = lambda[static_cast<Eigen::Index>(i)];
    if (!(l > 1e-9 * lambda_max && l > 0)) continue;  // in contact: as contact_nodes counts
    const int n = candidates_[i];
    const Vector3d k =
        nodal_strain_at(model_.mesh, assembler_, *model_.element, s, n, node_elements_[n])
            .segment<3>(3)
            .transpose();
    out.contact_curvature_min = any ? out.contact_curvature_min.cwiseMin(k) : k;
    out.contact_curvature_max = any ? out.contact_curvature_max.cwiseMax(k) : k;
    any = true;
  }
  if (any && model_.symmetry_factor > 1) {
    const double k12 =
        std::max(std::abs(out.contact_curvature_min[1]), std::abs(out.contact_curvature_max[1]));
    out.contact_curvature_min[1] = -k12;
    out.contact_curvature_max[1] = k12;
  }
}

IndentationState IndentationProblem::evaluate(const cont::Vector& z, double h) {
  if (cached_state_ && h == cached_h_ && z.size() == cached_z_.size() && z == cached_z_)
    return *cached_state_;
  ++counters_.evaluations;
  const int nf = chart_.size();
  const double sym = model_.symmetry_factor;
  IndentationState out;
  out.depth = h;
  const std::vector<NodeState> s = node_states(z);
  Vector3d total = Vector3d::Zero();  // sum of the support reactions (internal force there)
  if (model_.kinematics == Kinematics::kLinear) {
    const cont::Vector x = z.head(nf);
    out.energy = sym * 0.5 * x.dot(reference_tangent_ * x);
    out.reaction = -sym * reaction_row_.dot(x);
  } else {
    // Converged points are where the last residual was assembled: usually cached.
    const Assembly& a = shell_.force_at(z.head(nf));
    out.energy = sym * a.energy;
    for (int dof : dofs_.prescribed_dofs())
      if (dof % kShellNodeDofs < 3) total[dof % kShellNodeDofs] += a.internal_force[dof];
    out.reaction = -sym * total.dot(direction_);
  }

  kinematic_quantities(z, s, out);
  local_quantities(z, out);
  contact_curvatures(z, s, out);
  out.min_gap = std::numeric_limits<double>::infinity();
  out.min_multiplier = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < candidates_.size(); ++i) {
    const int n = candidates_[i];
    const double lambda = z[nf + static_cast<int>(i)];
    const int k = static_cast<int>(i);
    const double depth = face_depth(n, z, h);
    const bool hits = weighted_ || gap(k, s, depth, false).hits;
    const double g = contact_gap(k, z, s, depth, lambda);  // to the flattened face
    out.nodes.push_back(n);
    out.multipliers.push_back(lambda);
    out.gaps.push_back(hits ? g : std::numeric_limits<double>::infinity());
    out.pressures.push_back(lambda / (weighted_ ? weighted_->w[k] : tributary_area_[n]));
    out.min_multiplier = std::min(out.min_multiplier, lambda);
    if (hits) {
      out.min_gap = std::min(out.min_gap, g);
      out.max_complementarity = std::max(out.max_complementarity, std::abs(lambda * g));
    }
  }
  cached_z_ = z;
  cached_h_ = h;
  cached_state_ = std::make_unique<IndentationState>(out);
  return out;
}

}  // namespace si
