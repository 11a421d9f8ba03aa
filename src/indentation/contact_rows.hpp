// The complementarity rows of a contact body over its candidate nodes, shared by the nodal gaps
// (nodal_gaps.hpp) and the weighted gaps (weighted_gaps.hpp), which differ only in the gap g_i
// and its gradient G_i. One unknown per candidate, lambda_i >= 0, its contact force along the
// direction of travel (N; weighted gaps: t-bar_i w_i), and one row
//     phi(lambda_i, kappa (g_i(x, h - u_i) + c_i lambda_i)) = 0
// with phi the NCP function (contact/ncp_function.hpp: Fischer-Burmeister, or min for the
// active-set cross-check), kappa the stiffness scale (N/mm) that makes lambda and kappa g
// comparable, and the local law's dent u_i and compliance c_i (local_approach.hpp). Beside the
// indenter's path a gap is far (1e6 mm): phi then pins lambda to zero.
//
// Candidates: the nodes whose contact point the indenter can reach within `candidate_depth` of
// travel past first touch; adapt() grows the set, after each accepted point, by every node whose
// contact point the indenter can now reach within that depth (the set follows the deformed shell)
// and the nodes within a few spacings of those (a margin, so that it grows in few events).
#pragma once

#include <set>
#include <vector>

#include "contact/ncp_function.hpp"
#include "indentation/contact_body.hpp"
#include "indentation/contact_term.hpp"
#include "indentation/local_approach.hpp"
#include "indentation/node_row.hpp"
#include "indentation/shell_part.hpp"

namespace si {

// What the contact rows of a body share with the problem.
struct ContactRowsSetting {
  const ShellPart& shell;
  const ContactBody& body;
  double kappa = 1;  // N/mm
  NcpFunction ncp = NcpFunction::kFischerBurmeisterMin;
  double candidate_depth = 12;  // mm of travel past first touch
};

class ContactRows : public ContactTerm {
 public:
  explicit ContactRows(const ContactRowsSetting& setting);
  ContactRows(const ContactRows&) = delete;  // approach_ may point at no_approach_
  ContactRows& operator=(const ContactRows&) = delete;

  // The local law the rows see (kept by reference; none unless set). Not const: a non-local
  // law's coupling follows the contact (adapt()).
  void set_approach(LocalApproach& approach) { approach_ = &approach; }
  // The law's adapted state (LocalApproach::adapted), for a checkpoint.
  std::vector<double> approach_state() const { return approach_->adapted(); }
  bool restore_approach_state(const std::vector<double>& s) {
    return approach_->restore_adapted(s);
  }

  int size() const override { return static_cast<int>(candidates_.size()); }
  const std::vector<int>& candidates() const { return candidates_; }
  // Replaces the candidate set (mesh nodes).
  void set_candidates(const std::vector<int>& nodes);
  Eigen::Ref<const cont::Vector> multipliers(const cont::Vector& z) const { return unknowns(z); }
  // T_N (N, whole shell) from the rows' multipliers: their sum times the symmetry factor, the one
  // rule of quantities() and IndentationProblem::indenter_force.
  double total_force(const Eigen::Ref<const Eigen::VectorXd>& multipliers) const;

  void add_pattern(Triplets& t) const override;
  // A non-local law's coupled candidates (LocalApproach::coupling_members), their rows' b as of
  // the last add_jacobian.
  RowCoupling row_coupling() const override;
  void locate(const SparseMatrix& J) override;
  void residual(const TermPoint& p, cont::Vector& F) override;
  void residual_p(const TermPoint& p, cont::Vector& out) override;
  void signature(const TermPoint& p, std::vector<int>& out) const override;
  void active_gradients(const TermPoint& p, Triplets& out,
                        std::vector<int>& multiplier_index) const override;
  bool adapt(const TermPoint& p) override;
  // Force (T_N, whole shell), nodes in contact, their area and the contact radius.
  void quantities(const TermPoint& p, IndentationState& out) const override;
  // The curvature extremes over the nodes in contact and the per-candidate KKT values.
  void outputs(const TermPoint& p, IndentationState& out) const override;

  // Linear kinematics (the fast path, linear_indentation.hpp): the gap gradients at the
  // reference state (one row per candidate, free-dof columns), the gaps at h = 0 of the
  // undeformed shell (g = g0 - h + C x), and the local law's column j of d layer / d lambda
  // added to `column` (mm/N).
  virtual SparseMatrix gap_matrix(const TermPoint& reference) const = 0;
  Eigen::VectorXd reference_gaps(const TermPoint& reference) const;
  void add_compliance_column(int j, Eigen::VectorXd& column) const {
    approach_->add_compliance_column(candidates_, j, column);
  }
  // lambda_i over this is candidate i's contact pressure, MPa (the state's `pressures`).
  double pressure_area_of(int i) const { return pressure_area(i); }

 protected:
  // Value slots in J of candidate i's entries on its node's equations.
  using Slots = NodeRowSlots;

  // Candidate i's gap (mm) at the face depth `depth`, far beside the indenter's path.
  virtual double gap_value(int i, const TermPoint& p, double depth) const = 0;
  // Whether candidate i's contact point lies on the indenter's path (its row is a gap row).
  virtual bool hits(int i, const TermPoint& p, double depth) const = 0;
  // Candidate i's gradient entries (free-dof column, value) for active_gradients().
  virtual void gradient(int i, const TermPoint& p,
                        std::vector<std::pair<int, double>>& out) const = 0;
  // lambda_i over this is candidate i's contact pressure (MPa).
  virtual double pressure_area(int i) const = 0;
  // After the candidate set changed; `appended`: the old candidates are its head.
  virtual void candidates_changed(bool appended) = 0;

  // The local law at mesh node `node`: the dent (u, du/dalpha); at candidate i the layer's
  // approach under the multipliers of p.
  DentValue dent_at(int node, const cont::Vector& z) const { return approach_->dent(node, z); }
  double layer_at(int i, const TermPoint& p) const {
    return approach_->layer(candidates_, i, multipliers(p.z));
  }
  // Before a sweep over the candidates at p (LocalApproach::prepare).
  void prepare_layer(const TermPoint& p) const {
    approach_->prepare(candidates_, multipliers(p.z));
  }
  // The depth of the indenter into the contact face at mesh node `node`: h - u(r_node; alpha).
  double face_depth(int node, const cont::Vector& z, double h) const;
  // The gap candidate i's row sees: its gap plus the local layer's approach.
  double contact_gap(int i, const TermPoint& p, double depth) const;
  NcpValue complementarity(double lambda, double gap) const;
  // d phi_i / d lambda_i: phi_a, plus the thin layer's share through the gap.
  double multiplier_diagonal(int i, const NcpValue& phi) const;
  // The entries of candidate i's row and column that are the same for nodal and weighted gaps:
  // the diagonal and, with a power law's alpha, d g / d alpha = the dent's rate (`dent_rate`).
  void add_multiplier_terms(int i, const NcpValue& phi, double dent_rate, double* J) const;
  // A non-local law's entries of the rows in the other multipliers' columns,
  // b_i d layer_i / d lambda_j over its coupled candidates (row_coupling()): b_i = d_b kappa of
  // candidate i's row, per candidate.
  void set_layer_coupling(const Eigen::VectorXd& b);

  const ShellPart& shell() const { return setting_.shell; }
  const ContactBody& body() const { return setting_.body; }
  double kappa() const { return setting_.kappa; }

  const ContactRowsSetting setting_;
  std::vector<int> candidates_;
  std::vector<Slots> slots_;
  // The non-local law's coupled candidates, d layer / d lambda over them and their rows' b
  // (members numbered among these rows).
  RowCoupling coupling_;

 private:
  // Node spacings around each new candidate that a growth takes with it (adapt()).
  static constexpr double kGrowthMargin = 4.0;
  void add_margin(std::set<int>& added, const std::vector<bool>& is_candidate) const;

  LocalApproach no_approach_;
  LocalApproach* approach_ = &no_approach_;
};

}  // namespace si
