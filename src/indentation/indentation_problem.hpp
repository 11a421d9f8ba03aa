// The indentation problem as a continuation problem in the depth h (continuation/problem.hpp):
// a rigid indenter moves along its direction of travel e by t0 + h, t0 its first touch of the
// shell's contact face, and presses the shell frictionlessly (paper eqs 20-23, 72-80; P6, P7).
//
// A composition of parts, each in its own file:
//  * the shell (shell_part.hpp): unknowns x, its chart coordinates, and the equilibrium rows
//    r(x) - (the contact forces) = 0 with their Jacobian K (T + D); the kinematics live there;
//  * the indenter as a contact body (contact_body.hpp): its first touch and reach;
//  * contact terms (contact_term.hpp), each with its unknowns and rows: the complementarity rows
//    of the indenter's contact, with nodal gaps (nodal_gaps.hpp) or the paper's weighted gaps
//    and interpolated traction (weighted_gaps.hpp), and a local law: a power law's approach alpha
//    (power_law_approach.hpp) or a thin layer (thin_layer.hpp). contact_terms.cpp chooses them;
//  * the Jacobian's solver, chosen once (jacobian_solver.hpp); a power law's alpha borders the
//    Krylov solver's matrix.
// Unknowns z = [x ; the terms' unknowns, in order] (today [x ; lambda ; alpha]); the Jacobian is
// exact (generalised, at the kinks of the NCP function):
//     [ K - sum lambda_i dG_i    -G ]      then, for nonlinear kinematics, the chart transform
//     [ phi_b kappa G^T        phi_a ]      K T + D of shell_chart.hpp on the shell columns,
// with kappa a stiffness scale (the apex's translational stiffness along e, N/mm) that makes
// lambda and kappa g comparable. Linear kinematics: K, G and the gap are those of the reference
// state, so the only nonlinearity is phi; this is the paper's linear setting.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "contact/indenter.hpp"
#include "continuation/problem.hpp"
#include "indentation/contact_body.hpp"
#include "indentation/contact_terms.hpp"
#include "indentation/indentation_options.hpp"
#include "indentation/jacobian_solver.hpp"
#include "indentation/shell_part.hpp"
#include "indentation/state_probe.hpp"

namespace si {

// Where each kind of unknown sits in z = [x ; mu ; lambda ; alpha].
struct UnknownLayout {
  int shell = 0;        // x: z[0, shell)
  int frame = 0;        // mu: the support frame's multipliers (support_frame.hpp), if any
  int multipliers = 0;  // lambda: z[shell + frame, shell + frame + multipliers)
  int local = 0;        // alpha: 1 with a power-law local contact, else 0
  int frame_begin() const { return shell; }
  int lambda_begin() const { return shell + frame; }
  int alpha_index() const { return shell + frame + multipliers; }
  int size() const { return shell + frame + multipliers + local; }
};

class IndentationProblem : public cont::Problem {
 public:
  // Keeps references to model and indenter. `direction` is the indenter's unit direction of
  // travel. Throws an input error if the indenter cannot reach the shell or starts inside it.
  IndentationProblem(const ShellModel& model, const Indenter& indenter, const Vector3d& direction,
                     IndentationOptions options);
  ~IndentationProblem() override;

  int size() const override;
  UnknownLayout layout() const;
  bool residual(const cont::Vector& z, double h, cont::Vector& F) override;
  bool factorize(const cont::Vector& z, double h) override;
  bool solve(cont::Vector& b) override;
  bool residual_p(const cont::Vector& z, double h, cont::Vector& out) override;
  // Arclength metric: mean square of the shell coordinates (mm, rad; a power law's alpha counts
  // as one more) plus the mean square of the indenter's multipliers over kappa (mm) and that of
  // the support frame's, so that with
  // parameter weight 1 an arclength step is about a depth step (each shell point moves at most as
  // much as the indenter).
  double inner(const cont::Vector& a, const cont::Vector& b) const override;
  std::vector<std::string> monitor_names() const override;
  // The monitors need no assembly (the continuation evaluates them off the branch too).
  cont::Vector monitors(const cont::Vector& z, double h) override;
  // Without the damage probe unless a monitor in `which` reads it (StateMonitor::probed).
  cont::Vector monitor_subset(const cont::Vector& z, double h,
                              const std::vector<int>& which) override;
  std::vector<int> signature(const cont::Vector& z, double h) override;
  bool adapt(cont::Vector& z, double h) override;
  // The corrector's start for the step out of first touch (h = 0, undeformed) to depth h, from
  // set_first_step_start; none for any other step, or without one.
  cont::Vector corrector_start(const cont::Vector& z_from, double h_from, double h) override;
  // Where the first step's corrector starts: e.g. the linear-kinematics twin's state at the
  // step's depth (analysis/onset_watch.hpp), in this problem's layout; empty for none. The tangent
  // at first touch sees the one node that touches, where the step's solution presses several:
  // from it the first step took 6 Newton iterations on the 1e5-unknown cap, 12 (516 s) on the
  // 1e6. Empty function (the default): the predictor's start.
  using FirstStepStart = std::function<cont::Vector(double h)>;
  void set_first_step_start(FirstStepStart start) { first_step_start_ = std::move(start); }
  // Drops what one solve hands the next (the Jacobian solver's reused preconditioner or LU, the
  // terms' Newton guesses, the evaluate() cache): a resumed run, which starts without them, then
  // goes on bit for bit as the uninterrupted one.
  void reset_solver_caches() override;
  // The numerical error behind the last residual() or factorize() that returned false.
  std::string failure() const override { return failure_; }
  // A shell unknown's node (reference position, mm) and component, a contact row's candidate
  // node, a support frame row or the local approach (unknown_name.cpp).
  std::string unknown_name(int i) const override;
  // The gradients of the strongly active contact constraints with respect to the shell's free
  // dofs (one row per active constraint; spatial increments, before the chart transform), for
  // the tangent restricted to them; `multiplier_index` (if given) gets each row's multiplier in z.
  SparseMatrix active_constraint_gradients(const cont::Vector& z, double h,
                                           std::vector<int>* multiplier_index = nullptr) const;

  // Stability of a converged point (indentation_stability.cpp; docs/theory/continuation.md 12):
  // the Hessian of the Lagrangian in the shell's chart coordinates restricted to the strongly
  // active contact constraints. Provided without a local contact law (whose approach alpha and
  // compliant rows are not a constraint on the shell alone).
  bool provides_stability() const override;
  bool stability(const cont::Vector& z, double h, int modes, cont::Stability& out) override;
  // What stability() analyses: H (shell chart coordinates, symmetric, both triangles), the
  // active constraint rows A in the same coordinates, each row's multiplier in z, and the
  // relative asymmetry |H0 - H0'|_F / |H0|_F of T' J_xx before its symmetric part H was taken
  // (the Newton residual's order at a converged point).
  struct StabilityMatrices {
    SparseMatrix H;
    SparseMatrix A;
    std::vector<int> multipliers;
    double asymmetry = 0;
  };
  StabilityMatrices stability_matrices(const cont::Vector& z, double h);

  // The starting point: undeformed, no contact force (a solution at h = 0).
  cont::Vector initial_point() const;
  double first_touch() const { return body_.first_touch(); }
  double stiffness_scale() const { return kappa_; }
  const std::vector<int>& candidates() const { return contact_->candidates(); }
  // The local law's adapted state (an elastic face's zone: LocalApproach::adapted).
  std::vector<double> local_state() const { return contact_->approach_state(); }
  // Replaces the candidate set (mesh node indices) and the local law's state, resuming a run
  // whose set and law had adapted; false (nothing changed) if the state is not this law's.
  bool restore_contact(const std::vector<int>& nodes, const std::vector<double>& local_state);
  int num_shell_unknowns() const { return shell_.size(); }
  int num_local_unknowns() const { return layout().local; }
  // The support frame's rows (support_frame.hpp), or nullptr: the model rests on none.
  const SupportFrame* support_frame() const { return parts_.frame; }
  const LocalContactLaw& local_law() const { return options_.local; }
  // The whole-shell force scale for tolerances: max(T_N, kappa * 1 mm * 1e-3) at z.
  double force_scale(const cont::Vector& z) const;
  // The whole-shell indenter force T_N (N) at z, bit for bit evaluate(z, h).force, without the
  // rest of the state (energy, curvatures, the error estimate: a recovery over the whole mesh).
  double indenter_force(const cont::Vector& z) const;
  // The same from the indenter's multipliers alone (z's multiplier block, in its order).
  double indenter_force_of(const Eigen::Ref<const Eigen::VectorXd>& multipliers) const;

  std::vector<NodeState> node_states(const cont::Vector& z) const;

  // Linear kinematics only (the fast path, linear_indentation.hpp): the reference tangent K
  // (free dofs), the candidates' gap gradients C (one row per candidate, free-dof columns) and
  // the gaps at h = 0 of the undeformed shell, g0 (mm); then g = g0 - h + C x. With the
  // interpolated traction these are the weighted gaps over their weights (weighted_gaps.hpp).
  const SparseMatrix& linear_tangent() const { return shell_.reference_tangent(); }
  SparseMatrix contact_matrix() const;
  Eigen::VectorXd reference_gaps() const;
  // A linear local law's column j of the face's compliance over the candidates, added to
  // `column` (mm/N): c_L / A_j on the diagonal for the thin layer, the influence coefficients of
  // the elastic face; the fast path adds it to the Schur complement. A power-law local law is
  // nonlinear: the fast path refuses it (run_indentation_path routes it to the continuation).
  void add_local_compliance_column(int j, Eigen::VectorXd& column) const;

  IndentationState evaluate(const cont::Vector& z, double h);
  // What else the state carries from the displacement field (the failure indices of a run that
  // monitors damage, analysis/damage_probe.hpp), from now on; none by default. Set it before the
  // path starts: the monitors read it.
  void set_probe(std::shared_ptr<const StateProbe> probe);
  // The probe's part of the state (set_probe; nothing without one) at unknowns
  // z of this run, also of an earlier point whose candidate set was smaller (an event found
  // before the set grew: the candidates are appended, so z's multipliers are the set's head).
  IndentationState probe_at(const cont::Vector& z) const;
  const ShellModel& model() const { return model_; }
  IndentationCounters counters() const;
  // The preconditioned Krylov solver's work (zero with a direct LU).
  ContactJacobianCounters solver_counters() const { return solver_->counters(); }
  const DofMap& dofs() const { return shell_.dofs(); }
  const Assembler& assembler() const { return shell_.assembler(); }

 private:
  // The terms placed after the shell in z, and the Jacobian's pattern and slots built anew.
  void lay_out();
  void build_pattern();
  // r_free = r(x) - the terms' forces; returns the node states at z.
  const std::vector<NodeState>& shell_terms(const cont::Vector& z, double h, cont::Vector& r_free);
  // stability() from the Krylov solver's own factor at the point factorize() was last called at
  // (continuation/penalized_stability.hpp); false when that route does not apply (another point,
  // a direct solver, a penalised matrix that is not positive definite).
  bool penalized_stability(const cont::Vector& z, double h, int modes, cont::Stability& out);
  bool factored_at(const cont::Vector& z, double h) const;
  // Each mode v (shell part, chart coordinates) as unknowns z, its multipliers' part from
  // cont::multiplier_direction with the product H v given.
  void complete_modes(const std::function<cont::Vector(const cont::Vector&)>& H_times,
                      const SparseMatrix& A, const std::vector<int>& multipliers,
                      std::vector<cont::Vector>& modes) const;
  // The quantities of the monitors (no gaps, no assembly); the probe's only `with_probe`.
  void quantities(const cont::Vector& z, const std::vector<NodeState>& s, double h,
                  IndentationState& out, bool with_probe = true) const;
  // The probe's part at node states s; z's multiplier block may be the head of today's.
  void probe(const cont::Vector& z, const std::vector<NodeState>& s, IndentationState& out) const;

  const ShellModel& model_;
  IndentationOptions options_;
  ShellPart shell_;
  ContactBody body_;
  double kappa_ = 1;  // N/mm
  ContactParts parts_;
  ContactRows* contact_ = nullptr;  // the indenter's contact rows (in parts_)
  int border_ = 0;                  // bordering unknowns at the end of z (ContactTerm::borders)
  std::unique_ptr<JacobianSolver> solver_;
  std::shared_ptr<const StateProbe> probe_;
  FirstStepStart first_step_start_;
  SparseMatrix jacobian_;
  std::vector<int> k_to_j_;  // value slot of K's entries in jacobian_
  // Where jacobian_ was last assembled and factored, and its chart's rotation blocks: the
  // continuation factors at each converged point before it asks for its stability, which then
  // reads this Jacobian instead of assembling the same one again (indentation_stability.cpp).
  struct FactoredPoint {
    cont::Vector z;
    double h = 0;
    std::vector<ShellChart::RotationBlock> rotations;
  };
  std::unique_ptr<FactoredPoint> factored_;
  IndentationCounters counters_;
  std::string failure_;  // failure()
  // evaluate() at the last (z, h): the continuation's monitors and the output read the same point.
  cont::Vector cached_z_;
  double cached_h_ = 0;
  std::unique_ptr<IndentationState> cached_state_;
};

}  // namespace si
