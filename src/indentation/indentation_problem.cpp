#include "indentation/indentation_problem.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"

namespace si {

IndentationProblem::IndentationProblem(const ShellModel& model, const Indenter& indenter,
                                       const Vector3d& direction, IndentationOptions options)
    : model_(model),
      options_(std::move(options)),
      shell_(model, direction.normalized(), options_.threads),
      body_(indenter, direction.normalized(), model.mesh, options_.contact_offset,
            options_.candidate_depth) {
  // kappa: the apex's translational stiffness along the direction of travel.
  const SparseMatrix& K = shell_.reference_tangent();
  const int apex = model.apex_node();
  Matrix3d Ka = Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int ei = dofs().equation(DofMap::dof(apex, i)),
                ej = dofs().equation(DofMap::dof(apex, j));
      if (ei >= 0 && ej >= 0) Ka(i, j) = K.coeff(ei, ej);
    }
  const Vector3d& e = body_.direction();
  kappa_ = e.dot(Ka * e);
  SI_REQUIRE(kappa_ > 0, "indentation: the apex has no stiffness along the direction of travel");

  parts_ = make_contact_parts(
      options_, ContactRowsSetting{shell_, body_, kappa_, options_.ncp, options_.candidate_depth});
  contact_ = parts_.indenter;
  // Bordering terms come last (contact_term.hpp); the Krylov solver takes one bordering unknown.
  for (const auto& t : parts_.terms)
    if (t->borders()) border_ += t->size();
  SI_REQUIRE(parts_.terms.back()->borders() || border_ == 0,
             "indentation: a bordering contact term must be the last");
  const bool condensable =
      border_ <= 1 && std::all_of(parts_.terms.begin(), parts_.terms.end(),
                                  [](const auto& t) { return t->condensable() || t->borders(); });
  solver_ =
      make_jacobian_solver(options_.linear_solver, condensable, kappa_, options_.krylov_tolerance);
  lay_out();
  build_pattern();
}

IndentationProblem::~IndentationProblem() = default;

void IndentationProblem::lay_out() {
  int first = shell_.size();
  for (const auto& t : parts_.terms) {
    t->place(first);
    first += t->size();
  }
}

void IndentationProblem::build_pattern() {
  const SparseMatrix& K = shell_.reference_tangent();  // the shell's pattern
  Triplets t;
  t.reserve(K.nonZeros() + 36 * static_cast<std::size_t>(size() - shell_.size()));
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) t.emplace_back(it.row(), j, 0.0);
  for (const auto& term : parts_.terms) term->add_pattern(t);
  jacobian_ = SparseMatrix(size(), size());
  jacobian_.setFromTriplets(t.begin(), t.end());
  jacobian_.makeCompressed();
  k_to_j_.resize(K.nonZeros());
  for (int j = 0; j < K.outerSize(); ++j)
    for (int k = K.outerIndexPtr()[j]; k < K.outerIndexPtr()[j + 1]; ++k)
      k_to_j_[k] = value_slot(jacobian_, K.innerIndexPtr()[k], j);
  for (const auto& term : parts_.terms) term->locate(jacobian_);
  factored_.reset();
  solver_->pattern_changed();
}

UnknownLayout IndentationProblem::layout() const {
  const int frame = parts_.frame ? parts_.frame->size() : 0;
  return {shell_.size(), frame, contact_->size(),
          size() - shell_.size() - frame - contact_->size()};
}

int IndentationProblem::size() const {
  int n = shell_.size();
  for (const auto& t : parts_.terms) n += t->size();
  return n;
}

cont::Vector IndentationProblem::initial_point() const {
  return cont::Vector::Zero(size());
}

std::vector<NodeState> IndentationProblem::node_states(const cont::Vector& z) const {
  SI_REQUIRE(z.size() == size(), "indentation: unknown vector of the wrong size (" +
                                     std::to_string(z.size()) + " for " + std::to_string(size()) +
                                     ")");
  return shell_.states(z.head(shell_.size()));
}

void IndentationProblem::reset_solver_caches() {
  for (const auto& t : parts_.terms) t->reset_caches();
  cached_state_.reset();
  solver_->reset();
}

bool IndentationProblem::restore_contact(const std::vector<int>& nodes,
                                         const std::vector<double>& local_state) {
  for (int n : nodes)
    SI_REQUIRE(n >= 0 && n < model_.mesh.num_nodes(), "restore_contact: node out of range");
  if (!contact_->restore_approach_state(local_state)) return false;
  contact_->set_candidates(nodes);
  lay_out();
  build_pattern();
  return true;
}

const std::vector<NodeState>& IndentationProblem::shell_terms(const cont::Vector& z, double h,
                                                              cont::Vector& r_free) {
  const std::vector<NodeState>& states = shell_.force(z.head(shell_.size()), r_free);
  const TermPoint p{z, h, states};
  for (const auto& t : parts_.terms) t->add_shell_force(p, r_free);
  return states;
}

bool IndentationProblem::residual(const cont::Vector& z, double h, cont::Vector& F) {
  ++counters_.residuals;
  cont::Vector r;
  const std::vector<NodeState>* states = nullptr;
  try {
    states = &shell_terms(z, h, r);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    failure_ = e.what();
    return false;
  }
  F.resize(size());
  F.head(shell_.size()) = r;
  const TermPoint p{z, h, *states};
  for (const auto& t : parts_.terms) t->residual(p, F);
  return F.allFinite();
}

bool IndentationProblem::factorize(const cont::Vector& z, double h) {
  ++counters_.factorizations;
  const int nf = shell_.size();
  factored_.reset();
  cont::Vector r_free;
  const std::vector<NodeState>* states = nullptr;
  try {
    states = &shell_terms(z, h, r_free);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    failure_ = e.what();
    return false;
  }
  const SparseMatrix& K = shell_.tangent(z.head(nf));
  double* J = jacobian_.valuePtr();
  std::fill(J, J + jacobian_.nonZeros(), 0.0);
  for (int k = 0; k < K.nonZeros(); ++k) J[k_to_j_[k]] = K.valuePtr()[k];
  std::vector<ContactJacobianRow> rows;
  std::vector<ContactJacobianRow>* condensed = solver_->wants_condensed_rows() ? &rows : nullptr;
  const TermPoint p{z, h, *states};
  for (const auto& t : parts_.terms) t->add_jacobian(p, J, condensed);
  RowCoupling coupling;  // one term's at most (the contact rows' with an elastic face)
  for (const auto& t : parts_.terms) {
    RowCoupling c = t->row_coupling();
    if (c.empty()) continue;
    SI_REQUIRE(coupling.empty(), "indentation: more than one term couples its rows");
    for (int& i : c.members) i += t->first() - nf;
    coupling = std::move(c);
  }
  const std::vector<ShellChart::RotationBlock> rotations =
      shell_.to_chart(z.head(nf), r_free, jacobian_);
  try {
    solver_->factorize(jacobian_, nf, rotations, rows, border_, std::move(coupling));
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    failure_ = e.what();
    return false;
  }
  factored_.reset(new FactoredPoint{z, h, rotations});
  return true;
}

bool IndentationProblem::solve(cont::Vector& b) {
  ++counters_.solves;
  b = solver_->solve(b);
  return b.allFinite();
}

bool IndentationProblem::residual_p(const cont::Vector& z, double h, cont::Vector& out) {
  const std::vector<NodeState> s = node_states(z);
  out = cont::Vector::Zero(size());
  const TermPoint p{z, h, s};
  for (const auto& t : parts_.terms) t->residual_p(p, out);
  return true;
}

double IndentationProblem::force_scale(const cont::Vector& z) const {
  return std::max(std::abs(indenter_force(z)), kappa_ * 1e-3);
}

double IndentationProblem::indenter_force(const cont::Vector& z) const {
  return indenter_force_of(contact_->multipliers(z));
}

double IndentationProblem::indenter_force_of(
    const Eigen::Ref<const Eigen::VectorXd>& multipliers) const {
  return contact_->total_force(multipliers);
}

double IndentationProblem::inner(const cont::Vector& a, const cont::Vector& b) const {
  // By the layout, not by counting from the end: the multipliers sit between x and alpha.
  const UnknownLayout u = layout();
  const int lambda = u.lambda_begin(), nc = u.multipliers;
  // alpha (mm) counts as one more shell coordinate.
  double sum = (a.head(u.shell).dot(b.head(u.shell)) + a.tail(u.local).dot(b.tail(u.local))) /
               static_cast<double>(u.shell + u.local);
  if (nc > 0)
    sum += a.segment(lambda, nc).dot(b.segment(lambda, nc)) /
           (static_cast<double>(nc) * kappa_ * kappa_);
  if (u.frame > 0)
    sum += a.segment(u.frame_begin(), u.frame).dot(b.segment(u.frame_begin(), u.frame)) /
           (static_cast<double>(u.frame) * kappa_ * kappa_);
  return sum;
}

std::vector<std::string> IndentationProblem::monitor_names() const {
  std::vector<std::string> names;
  for (const StateMonitor& m : options_.monitors) names.push_back(m.name);
  return names;
}

void IndentationProblem::quantities(const cont::Vector& z, const std::vector<NodeState>& s,
                                    double h, IndentationState& out, bool with_probe) const {
  const int apex = model_.apex_node();
  out.apex_deflection = s[apex].u.dot(body_.direction());
  out.apex_mid_deflection = out.apex_deflection;
  out.apex_curvature = shell_.curvature(s, apex);
  const TermPoint p{z, h, s};
  for (const auto& t : parts_.terms) t->quantities(p, out);
  if (with_probe) probe(z, s, out);
}

void IndentationProblem::probe(const cont::Vector& z, const std::vector<NodeState>& s,
                               IndentationState& out) const {
  if (!probe_) return;
  const int first = contact_->first();
  const int given = std::min(static_cast<int>(z.size()) - first - layout().local, contact_->size());
  Eigen::VectorXd pressures = Eigen::VectorXd::Zero(contact_->size());
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(contact_->size());
  for (int i = 0; i < given; ++i) {
    forces[i] = z[first + i];
    pressures[i] = forces[i] / contact_->pressure_area_of(i);
  }
  const double whole_shell = model_.symmetry_factor * forces.sum();
  probe_->measure(ProbePoint{s, contact_->candidates(), pressures, forces, whole_shell}, out);
}

cont::Vector IndentationProblem::corrector_start(const cont::Vector& z_from, double h_from,
                                                 double h) {
  const bool from_first_touch = h_from == 0.0 && (z_from.array() == 0.0).all();
  if (!first_step_start_ || !from_first_touch) return {};
  cont::Vector z = first_step_start_(h);
  return z.size() == size() ? z : cont::Vector();
}

void IndentationProblem::set_probe(std::shared_ptr<const StateProbe> probe) {
  probe_ = std::move(probe);
  cached_state_.reset();
}

IndentationState IndentationProblem::probe_at(const cont::Vector& z) const {
  IndentationState out;
  probe(z, shell_.states(z.head(shell_.size())), out);
  return out;
}

cont::Vector IndentationProblem::monitors(const cont::Vector& z, double h) {
  IndentationState out;
  const bool cached =
      cached_state_ && h == cached_h_ && z.size() == cached_z_.size() && z == cached_z_;
  if (!cached) quantities(z, node_states(z), h, out);
  const IndentationState& s = cached ? *cached_state_ : out;
  cont::Vector m(static_cast<Eigen::Index>(options_.monitors.size()));
  for (std::size_t i = 0; i < options_.monitors.size(); ++i)
    m[static_cast<Eigen::Index>(i)] = options_.monitors[i].value(s);
  return m;
}

cont::Vector IndentationProblem::monitor_subset(const cont::Vector& z, double h,
                                                const std::vector<int>& which) {
  const auto& all = options_.monitors;
  const bool probed = std::any_of(which.begin(), which.end(),
                                  [&](int i) { return all[static_cast<std::size_t>(i)].probed; });
  IndentationState s;
  quantities(z, node_states(z), h, s, probed);
  cont::Vector m(static_cast<Eigen::Index>(which.size()));
  for (std::size_t i = 0; i < which.size(); ++i)
    m[static_cast<Eigen::Index>(i)] = all[static_cast<std::size_t>(which[i])].value(s);
  return m;
}

std::vector<int> IndentationProblem::signature(const cont::Vector& z, double h) {
  const std::vector<NodeState> s = node_states(z);
  std::vector<int> active;
  const TermPoint p{z, h, s};
  for (const auto& t : parts_.terms) t->signature(p, active);
  return active;
}

SparseMatrix IndentationProblem::active_constraint_gradients(
    const cont::Vector& z, double h, std::vector<int>* multiplier_index) const {
  const std::vector<NodeState> s = node_states(z);
  const TermPoint p{z, h, s};
  Triplets t;
  std::vector<int> rows;
  for (const auto& term : parts_.terms) term->active_gradients(p, t, rows);
  SparseMatrix G(static_cast<Eigen::Index>(rows.size()), shell_.size());
  G.setFromTriplets(t.begin(), t.end());
  if (multiplier_index) *multiplier_index = std::move(rows);
  return G;
}

bool IndentationProblem::adapt(cont::Vector& z, double h) {
  const std::vector<NodeState> s = node_states(z);
  std::vector<int> first, count;
  bool grown = false;
  const TermPoint p{z, h, s};
  for (const auto& t : parts_.terms) {
    first.push_back(t->first());
    count.push_back(t->size());
    if (t->adapt(p)) grown = true;
  }
  if (!grown) return false;
  lay_out();
  build_pattern();
  // The old unknowns at the head of each block, the new ones zero.
  const int nf = shell_.size();
  cont::Vector next = cont::Vector::Zero(size());
  next.head(nf) = z.head(nf);
  for (std::size_t k = 0; k < parts_.terms.size(); ++k)
    next.segment(parts_.terms[k]->first(), count[k]) = z.segment(first[k], count[k]);
  z = next;
  return true;
}

SparseMatrix IndentationProblem::contact_matrix() const {
  SI_REQUIRE(model_.kinematics == Kinematics::kLinear, "contact_matrix: linear kinematics only");
  const cont::Vector z0 = initial_point();
  const std::vector<NodeState> s = node_states(z0);
  return contact_->gap_matrix(TermPoint{z0, 0.0, s});
}

Eigen::VectorXd IndentationProblem::reference_gaps() const {
  const cont::Vector z0 = initial_point();
  const std::vector<NodeState> s = node_states(z0);
  return contact_->reference_gaps(TermPoint{z0, 0.0, s});
}

void IndentationProblem::add_local_compliance_column(int j, Eigen::VectorXd& column) const {
  contact_->add_compliance_column(j, column);
}

IndentationCounters IndentationProblem::counters() const {
  IndentationCounters c = counters_;
  c.tangent_assemblies = shell_.tangent_assemblies();
  c.force_assemblies = shell_.force_assemblies();
  return c;
}

IndentationState IndentationProblem::evaluate(const cont::Vector& z, double h) {
  if (cached_state_ && h == cached_h_ && z.size() == cached_z_.size() && z == cached_z_)
    return *cached_state_;
  ++counters_.evaluations;
  IndentationState out;
  out.depth = h;
  const std::vector<NodeState> s = node_states(z);
  shell_.energy_and_reaction(z.head(shell_.size()), out.energy, out.reaction);
  quantities(z, s, h, out);
  // Without a contact force nothing is loaded: the relative error of a zero field is round-off.
  out.error_estimate = out.force > 0 ? shell_.error_estimate(s) : 0.0;
  const TermPoint p{z, h, s};
  for (const auto& t : parts_.terms) t->outputs(p, out);
  // The support frame is a support too: its force joins the reaction along -e.
  if (parts_.frame) out.reaction -= out.frame_force * parts_.frame->normal().dot(body_.direction());
  cached_z_ = z;
  cached_h_ = h;
  cached_state_ = std::make_unique<IndentationState>(out);
  return out;
}

}  // namespace si
