// The indentation problem as a continuation problem in the depth h (continuation/problem.hpp):
// a rigid indenter moves along its direction of travel e by t0 + h, t0 its first touch of the
// shell's contact face, and presses the shell frictionlessly (paper eqs 20-23, 72-80; P6, P7).
//
// Unknowns z = [x ; lambda ; alpha] (UnknownLayout): x the shell's chart coordinates
// (model/shell_chart.hpp; for linear kinematics the element's linear-mode dofs, the same
// numbers), lambda >= 0 one Lagrange multiplier per candidate node: its contact force along e, N
// (contact/node_gap.hpp), and, with a power-law local contact (contact/local_contact_law.hpp,
// docs/theory/local-indentation.md), the local approach alpha (mm) of the indenter towards the
// shell's contact face. Equations:
//     r(x) - sum_i lambda_i G_i(x) = 0               equilibrium (free dofs)
//     phi(lambda_i, kappa g_i(x, h - u_i(alpha))) = 0  complementarity, per candidate
//     s sum_i lambda_i - k sgn(alpha) |alpha|^1.5 = 0  local law (power law only; s = symmetry
//                                                       factor: the law holds for the whole shell)
// with g_i the gap along the direction of travel (travel_gap.hpp), G_i its gradient in the
// node's dofs, phi the Fischer-Burmeister function (or min, for the active-set cross-check),
// kappa a stiffness scale (the apex's translational stiffness along e, N/mm) that makes
// lambda and kappa g comparable. The Jacobian is exact (generalised, at the kinks of phi):
//     [ K - sum lambda_i dG_i    -G ]      then, for nonlinear kinematics, the chart transform
//     [ phi_b kappa G^T        phi_a ]      K T + D of shell_chart.hpp on the shell columns.
// Linear kinematics: K, G and the gap are those of the reference state (linearised gap,
// node_gap.hpp), so the only nonlinearity is phi; this is the paper's linear setting.
// Local law: the contact face is dented by Hertz's profile u_i = u(r_i; alpha) of the law
// (hertz_dent.hpp; alpha at the axis, r_i the node's distance from the indenter's axis in the
// reference configuration), so the indenter's travel into node i's face is h - u_i: a flat punch
// at depth h - alpha inside the patch r <= (R alpha)^0.5, the half-space's surface displacement
// outside. The law is written as force in terms of alpha (not alpha = (F/k)^(2/3), whose
// derivative is infinite at F = 0): its derivative 1.5 k alpha^0.5 is finite everywhere and zero
// at the start, where the alpha column still has d_b kappa du/dalpha = d_b kappa in the row of
// the first-touch node (its r is 0: inside the patch), so the Jacobian stays regular
// (local-indentation.md 3). With the thin-layer law (vam) each gap gains
// c_L lambda_i / A_i instead, A_i the node's tributary area: no extra unknown. The linear fast
// path refuses the power law (nonlinear) and carries the thin layer.
//
// Candidates: the nodes whose contact point the indenter can reach within `candidate_depth` of
// travel past first touch (reference configuration). adapt() grows the set, after each accepted
// point, by every node whose contact point the indenter can now reach within that depth.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis/chart_assembly.hpp"
#include "analysis/contact_jacobian_solver.hpp"
#include "analysis/interpolated_contact.hpp"
#include "analysis/shell_model.hpp"
#include "contact/indenter.hpp"
#include "contact/local_contact_law.hpp"
#include "contact/ncp_function.hpp"
#include "contact/node_gap.hpp"
#include "continuation/problem.hpp"
#include "model/assembler.hpp"
#include "model/dof_map.hpp"
#include "model/linear_solver.hpp"
#include "model/shell_chart.hpp"

namespace si {

// GMRES on the Jacobian preconditioned by a Cholesky factorization of its condensed shell block.
inline const char* const kPreconditionedKrylov = "cholesky_gmres";

struct IndentationOptions {
  double contact_offset = 0;    // c: contact face above the reference surface along d, mm
  double candidate_depth = 12;  // mm of travel past first touch (see the header)
  // Fischer-Burmeister on the feasible quadrant, min outside (ncp_function.hpp); kMin for the
  // active-set cross-check.
  NcpFunction ncp = NcpFunction::kFischerBurmeisterMin;
  // The Jacobian's solver: kPreconditionedKrylov (contact_jacobian_solver.hpp; an LU of the
  // Jacobian where it cannot help) or a direct LU, "umfpack" | "klu" (the Jacobian is unsymmetric).
  // The interpolated traction's rows span several nodes: it uses the direct LU. A power-law
  // local contact's unknown alpha borders the Krylov solver's matrix
  // (contact_jacobian_solver.hpp).
  std::string linear_solver = "cholesky_gmres";
  // kPreconditionedKrylov: GMRES stops at a relative residual of krylov_tolerance. The Newton
  // corrections need no more than 1e-6: an inexact Newton method with a constant forcing term
  // (Dembo, Eisenstat & Steihaug 1982, SIAM J. Numer. Anal. 19:400-408) has
  // ||F_k+1|| <= eta ||F_k|| + O(||F_k||^2), and eta = 1e-6 is far below the contraction Newton
  // reaches within the corrector's tolerance: the iteration counts are those of exact solves
  // (measured identical on the 1e4-unknown cap over 0-10 mm) at 2.5 instead of 3.9 products per
  // solve. Convergence is judged on the residual, so eta does not limit the solution's accuracy;
  // the tangents and the bordered solves of the continuation carry errors of order eta.
  double krylov_tolerance = 1e-6;
  int threads = 0;  // element assembly (0 = OpenMP default)
  // The paper's option (contact.traction: interpolated; interpolated_contact.hpp), linear
  // kinematics only: the traction is interpolated from nodal values t-bar_i and the gaps are the
  // weighted gaps. The unknowns stay nodal forces, lambda_i = t-bar_i w_i (N), and the gap of
  // candidate i is its weighted gap over w_i, (g~0_i - h w_i + C~_i x) / w_i (mm): a positive
  // scaling of the paper's rows that leaves the solution, t-bar = lambda / w, unchanged and lets
  // kappa, the force scale and the fast path apply as they are.
  bool interpolated_traction = false;
  InterpolatedContactOptions interpolated;
  LocalContactLaw local;  // local contact in series (none by default)
};

// Where each kind of unknown sits in z = [x ; lambda ; alpha].
struct UnknownLayout {
  int shell = 0;        // x: z[0, shell)
  int multipliers = 0;  // lambda: z[shell, shell + multipliers)
  int local = 0;        // alpha: 1 with a power-law local contact, else 0
  int lambda_begin() const { return shell; }
  int alpha_index() const { return shell + multipliers; }
  int size() const { return shell + multipliers + local; }
};

// Everything a user wants at one converged point (whole-shell values: symmetry applied).
struct IndentationState {
  double depth = 0;            // h, mm
  double force = 0;            // T_N = sum of multipliers, N
  double reaction = 0;         // support reactions along -e, N (equals force at equilibrium)
  double apex_deflection = 0;  // apex mid-surface displacement along e, mm
  double contact_radius = 0;   // largest distance from the indenter's axis of a node in contact
  double contact_area = 0;     // tributary area of the nodes in contact, mm^2
  int contact_nodes = 0;       // nodes in contact (whole-shell count is not reconstructed)
  double energy = 0;           // strain energy, N mm
  // Local contact (zero without): the approach of the indenter towards the contact face at the
  // apex (alpha for a power law, c_L p at the apex node for the thin layer), mm, and the energy
  // stored in the local compliance, N mm (work = energy + local_energy).
  double local_indentation = 0;
  double local_energy = 0;
  Vector3d apex_curvature = Vector3d::Zero();  // k11, k12 + k21, k22 at the apex, 1/mm
  // Extremes of the same curvatures over the nodes in contact (paper-notes item 7: the paper's
  // figures do not say where their curvatures are taken). Quarter models: k12 changes sign in
  // the mirrored quadrants, so its extremes are -+ max |k12|.
  Vector3d contact_curvature_min = Vector3d::Zero(), contact_curvature_max = Vector3d::Zero();
  // KKT residuals: min gap (mm), min multiplier (N), max |lambda_i g_i| (N mm).
  double min_gap = 0, min_multiplier = 0, max_complementarity = 0;
  std::vector<int> nodes;           // candidate nodes
  std::vector<double> multipliers;  // lambda per candidate, N
  std::vector<double> gaps;         // g per candidate, mm
  std::vector<double> pressures;    // lambda / tributary area per candidate, MPa (interpolated
                                    // traction: lambda / w = t-bar, the nodal traction)
};

// Work done so far, for benchmarks and the run summary.
struct IndentationCounters {
  long residuals = 0;           // residual() calls (an assembly unless the last one was at z)
  long factorizations = 0;      // factorize() calls: Jacobian fills + factorizations
  long solves = 0;              // back-substitutions
  long evaluations = 0;         // evaluate() calls that were not cached (output, monitors)
  long tangent_assemblies = 0;  // element assemblies actually computed, force + tangent
  long force_assemblies = 0;    // and force only (nonlinear kinematics)
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
  Eigen::Ref<const cont::Vector> multipliers(const cont::Vector& z) const {
    return z.segment(chart_.size(), static_cast<Eigen::Index>(candidates_.size()));
  }
  // The depth of the indenter into the contact face at mesh node `node`: h - u(r_node; alpha)
  // with a power-law local law (h - alpha inside the patch), h otherwise.
  double face_depth(int node, const cont::Vector& z, double h) const;
  bool residual(const cont::Vector& z, double h, cont::Vector& F) override;
  bool factorize(const cont::Vector& z, double h) override;
  bool solve(cont::Vector& b) override;
  bool residual_p(const cont::Vector& z, double h, cont::Vector& out) override;
  // Arclength metric: mean square of the shell coordinates (mm, rad; alpha counts as one more)
  // plus the mean square of the multipliers over kappa (mm), so that with parameter weight 1 an
  // arclength step is about a depth step (each shell point moves at most as much as the indenter).
  double inner(const cont::Vector& a, const cont::Vector& b) const override;
  std::vector<std::string> monitor_names() const override;
  // The monitors of a state, in monitor_names() order.
  static cont::Vector monitor_vector(const IndentationState& s);
  cont::Vector monitors(const cont::Vector& z, double h) override;
  std::vector<int> signature(const cont::Vector& z, double h) override;
  bool adapt(cont::Vector& z, double h) override;

  // The starting point: undeformed, no contact force (a solution at h = 0).
  cont::Vector initial_point() const;
  double first_touch() const { return t0_; }
  double stiffness_scale() const { return kappa_; }
  const std::vector<int>& candidates() const { return candidates_; }
  // Replaces the candidate set (resuming a run whose set had grown): mesh node indices.
  void restore_candidates(const std::vector<int>& nodes);
  int num_shell_unknowns() const { return chart_.size(); }
  int num_local_unknowns() const { return layout().local; }
  const LocalContactLaw& local_law() const { return options_.local; }
  // The whole-shell force scale for tolerances: max(T_N, kappa * 1 mm * 1e-3) at z.
  double force_scale(const cont::Vector& z) const;

  std::vector<NodeState> node_states(const cont::Vector& z) const;

  // Linear kinematics only (the fast path, linear_indentation.hpp): the reference tangent K
  // (free dofs), the candidates' gap gradients C (one row per candidate, free-dof columns) and
  // the gaps at h = 0 of the undeformed shell, g0 (mm); then g = g0 - h + C x. With the
  // interpolated traction these are the weighted gaps over their weights (IndentationOptions).
  const SparseMatrix& linear_tangent() const { return reference_tangent_; }
  SparseMatrix contact_matrix() const;
  Eigen::VectorXd reference_gaps() const;
  // Thin-layer local law: each candidate's local compliance c_L / A_i, mm/N (zeros otherwise);
  // the fast path adds it to the diagonal of the Schur complement. A power-law local law is
  // nonlinear: the fast path refuses it (run_indentation_path routes it to the continuation).
  Eigen::VectorXd layer_compliances() const;
  IndentationState evaluate(const cont::Vector& z, double h);
  const ShellModel& model() const { return model_; }
  IndentationCounters counters() const {
    IndentationCounters c = counters_;
    c.tangent_assemblies = shell_.tangent_assemblies();
    c.force_assemblies = shell_.force_assemblies();
    return c;
  }
  // The preconditioned Krylov solver's work (zero with a direct LU).
  ContactJacobianCounters solver_counters() const {
    return krylov_ ? krylov_->counters() : ContactJacobianCounters{};
  }
  const DofMap& dofs() const { return dofs_; }
  const Assembler& assembler() const { return assembler_; }

 private:
  struct CandidateSlots;
  struct WeightedGaps;
  void choose_candidates(const std::vector<int>& nodes);
  void measure_dent_radii(const std::vector<Vector3d>& points, int first);
  // The local law's dent at mesh node `node` and its rate d/dalpha (zero without a power law).
  DentValue dent(int node, const cont::Vector& z) const;
  void build_pattern();
  NodeGap gap(int i, const std::vector<NodeState>& s, double h, bool derivative) const;
  // Candidate i's gap value (mm) at its face depth (h - u_i): the node's gap, or its weighted
  // gap (interpolated traction); contact_gap adds the thin-layer approach of its multiplier.
  double gap_value(int i, const cont::Vector& z, const std::vector<NodeState>& s,
                   double depth) const;
  double contact_gap(int i, const cont::Vector& z, const std::vector<NodeState>& s, double depth,
                     double lambda) const;
  // phi(lambda, kappa gap) with the touch's derivatives for a gap within roundoff (power law).
  NcpValue complementarity(double lambda, double gap) const;
  double multiplier_diagonal(int i, const NcpValue& phi) const;
  void add_multiplier_terms(int i, const NcpValue& phi, double dent_rate, double* J) const;
  void build_weighted_gaps();
  // Thin-layer local law: the approach at candidate i for its multiplier, c_L lambda_i / A_i.
  double layer_approach(int i, double lambda) const;
  void local_quantities(const cont::Vector& z, IndentationState& out) const;
  void contact_curvatures(const cont::Vector& z, const std::vector<NodeState>& s,
                          IndentationState& out) const;
  const std::vector<NodeState>& shell_terms(const cont::Vector& z, double h, cont::Vector& r_free);
  void build_reaction_row();
  void kinematic_quantities(const cont::Vector& z, const std::vector<NodeState>& s,
                            IndentationState& out) const;

  const ShellModel& model_;
  const Indenter& indenter_;
  Vector3d direction_;
  IndentationOptions options_;
  DofMap dofs_;
  Assembler assembler_;
  ShellChart chart_;
  ChartAssembly shell_;  // nonlinear kinematics: force and tangent at the last x
  // K at the reference state: the Jacobian's pattern, and the tangent of linear kinematics.
  SparseMatrix reference_tangent_;
  std::vector<NodeState> linear_states_;  // linear kinematics: node states at the last x
  Eigen::VectorXd reaction_row_;          // linear kinematics: support reaction along e = r_e . x
  double t0_ = 0;                         // first touch travel
  double touch_roundoff_ = 0;             // mm: a gap below it is a touch (complementarity())
  double kappa_ = 1;                      // N/mm
  std::vector<int> candidates_;
  std::vector<NodeContactGeometry> geometry_;        // per mesh node
  std::vector<double> tributary_area_;               // per mesh node, mm^2
  std::vector<double> dent_radius_;                  // per mesh node: r of the dent profile, mm
  mutable std::optional<DentProfile> dent_profile_;  // the dent at the last alpha (dent())
  mutable std::vector<double> touch_guess_;          // per candidate: last s(p), a Newton guess
  std::vector<std::vector<int>> neighbours_;         // per mesh node
  std::vector<std::vector<int>> node_elements_;      // per mesh node: the elements containing it
  std::vector<int> support_elements_;                // elements with a prescribed translation
  SparseMatrix jacobian_;
  std::vector<int> k_to_j_;  // value slot of K's entries in jacobian_
  std::vector<CandidateSlots> slots_;
  std::unique_ptr<WeightedGaps> weighted_;         // interpolated traction only
  std::unique_ptr<LinearSolver> solver_;           // a direct LU of the Jacobian, or
  std::unique_ptr<ContactJacobianSolver> krylov_;  // the preconditioned Krylov solver
  int alpha_diagonal_ = -1;                        // (alpha, alpha) with a power-law local contact
  IndentationCounters counters_;
  // evaluate() at the last (z, h): the continuation's monitors and the output read the same point.
  cont::Vector cached_z_;
  double cached_h_ = 0;
  std::unique_ptr<IndentationState> cached_state_;
};

// The contact face offset of a case: the laminate's top face (contact.surface: outer) or its
// mid-surface (contact.surface: mid, the paper's choice), measured from the reference surface.
double contact_face_offset(const CaseFile& c);

}  // namespace si
