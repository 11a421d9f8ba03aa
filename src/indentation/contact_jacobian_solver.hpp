// Linear solves with the indentation problem's Jacobian (indentation_problem.hpp)
//     J = [ A        -G  ]    A   = (K - sum_i lambda_i dG_i) T + D    (shell_chart.hpp)
//         [ b G~^T   Da  ]    G~  = T^T G,  b_i = phi_b kappa,  Da = diag(phi_a)
// by GMRES on J itself (exact), right-preconditioned with a Cholesky factorization of the
// symmetric positive-definite matrix
//     H = sym(T^T A) + sum_i (b_i / a_i) G~_i G~_i^T,    a_i = max(phi_a, eps b_i / kappa),
// the shell block premultiplied by T^T (which makes it the chart Hessian up to the drilling
// term D and the asymmetry of K, both proportional to the residual) with the complementarity
// rows condensed onto it (from row i: dlambda_i = (r_i - b_i G~_i^T dx) / a_i). For a fully
// active candidate (phi_a = 0) the condensation is a penalty of weight kappa / eps; GMRES removes
// the difference. Why: CHOLMOD's supernodal Cholesky of the shell block is about twice as fast as
// UMFPACK's LU of J, its solves three times (docs/performance.md), and its pattern never changes
// with the candidate set. Where H is not positive definite (past a limit point) or GMRES does not
// converge, the solve falls back to an LU of J (the `fallback` solver, UMFPACK by default). Where
// that LU runs out of memory (a million unknowns), the preconditioner is made from an LDL' of H
// without pivoting (exact for an indefinite H, slower than its Cholesky), and no LU is tried
// again.
// Candidates appended to the set (same shell block) keep the factor: their rows enter the
// preconditioner uncondensed until the next refresh.
// Rows that couple each other (Da not diagonal: the elastic face's compliance over its zone,
// given beside J: row_coupling.hpp) are eliminated exactly: the preconditioner adds a Woodbury
// correction over the coupled rows to the factor of H (coupled_rows.hpp).
// A border (one trailing unknown whose row and column couple the contact rows, the power-law
// local contact's approach alpha, power_law_approach.hpp) stays in J for GMRES; the
// preconditioner eliminates it by block elimination through the condensed factor P,
//     y_a = (r_a - d^T P^-1 r) / (e - d^T P^-1 c),   y = P^-1 r - (P^-1 c) y_a,
// (Golub & Van Loan 2013, 4.6; c, d, e the border's column, row and corner), which costs one
// more application of P per linearisation instead of a second Krylov solve.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "indentation/contact_jacobian_row.hpp"
#include "indentation/coupled_lu.hpp"
#include "indentation/coupled_rows.hpp"
#include "model/shell_chart.hpp"
#include "solvers/gmres.hpp"
#include "solvers/linear_solver.hpp"

namespace si {

struct ContactJacobianCounters {
  long cholesky = 0;         // Cholesky factorizations of H
  long ldlt = 0;             // LDL' factorizations of an indefinite H (no LU in memory)
  long lu_fallbacks = 0;     // factorizations of J by the fallback LU
  long krylov_solves = 0;    // GMRES solves
  long krylov_products = 0;  // products with J in them
};

class ContactJacobianSolver {
 public:
  // kappa: the problem's stiffness scale (N/mm). fallback: an LU solver (linear_solver.hpp).
  // relative_tolerance: GMRES stops at ||J y - b|| <= relative_tolerance ||b|| (in (0, 1)).
  ContactJacobianSolver(double kappa, LinearSolverKind fallback, double relative_tolerance = 1e-12);
  // The same with the fallback LU made by `fallback` (tests give one that fails as they need).
  ContactJacobianSolver(double kappa, LinearSolverFactory fallback,
                        double relative_tolerance = 1e-12);
  ~ContactJacobianSolver();

  // J: the Jacobian (num_shell shell rows/columns first, then one row/column per row of
  // `rows`, in order, then `border` (0 or 1) bordering unknowns), its pattern fixed until the
  // next call, and the contact rows' couplings kept beside it (row_coupling.hpp; the matrix
  // solved is J plus them). Throws a numerical si::Error if neither route can factor it
  // (singular J).
  void factorize(const SparseMatrix& J, int num_shell,
                 const std::vector<ShellChart::RotationBlock>& rotations,
                 const std::vector<ContactJacobianRow>& rows, int border = 0,
                 RowCoupling coupling = {});
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs);

  const ContactJacobianCounters& counters() const { return counters_; }

  // The stability analysis's factor (jacobian_solver.hpp, penalized_shell): the preconditioner
  // made anew at the last factorize()'s linearisation with weight kappa / floor on the listed
  // rows and none on the others. false if there is none to make (a border, this linearisation on
  // the LU) or it is not positive definite; the solver is then as factorize() left it.
  bool refresh_penalized(const std::vector<int>& rows);
  // P^-1 r on the shell block with the current factor (chart coordinates).
  Eigen::VectorXd solve_shell_block(const Eigen::VectorXd& r) const;
  // G~_i^T of the listed rows of the last factorize(): rows.size() x num_shell.
  SparseMatrix chart_gradients(const std::vector<int>& rows) const;

  // Forgets the preconditioner and the fallback LU (the next factorize() makes fresh ones), as a
  // new solver would have none: the solves that follow are those of a new solver, bit for bit.
  void forget_preconditioner();

 private:
  struct RotationSlots {
    int a = -1, b = -1;  // slots of (eq_a, c) and (eq_b, c) in H_ (-1: prescribed component)
    int block = 0;       // index into the rotation blocks
  };
  void analyze_shell(const SparseMatrix& J, int num_shell);
  void map_jacobian(const SparseMatrix& J);
  bool refresh_preconditioner();
  // H = sym(T^T A) + sum_i (b_i / a_i) G~_i G~_i^T over `condensed` (the current rows with their
  // weights), factored; kept with its rows on success.
  // `indefinite`: whether the LDL' of H may make it where H is not positive definite.
  enum class Indefinite {
    kNone,      // H's Cholesky or nothing
    kIfNeeded,  // H's Cholesky, else its LDL'
    kOnly,      // the LDL' only: H's Cholesky failed at this linearisation already
  };
  bool refresh_with(const std::vector<ContactJacobianRow>& condensed, Indefinite indefinite);
  // Cholesky of H_ as it is; false (refresh_failure_ says why) if it fails.
  bool factor_h();
  // H_'s Cholesky (unless kOnly), else (unless kNone) its LDL' (ldlt_solver.hpp); sets factor_.
  bool factor_shell_block(Indefinite indefinite);
  void apply_preconditioner(const Eigen::VectorXd& in, Eigen::VectorXd& out) const;
  // P^-1 on the shell and contact rows (in and out without the border).
  void apply_condensed(const Eigen::VectorXd& in, Eigen::VectorXd& out) const;
  // The border's c, d, e from J, and P^-1 c and the pivot e - d^T P^-1 c with the current P;
  // false if the pivot vanishes.
  bool prepare_border();
  // The LU of J; where it runs out of memory and `may_ldlt` (the caller's H of rows_ has just
  // failed its Cholesky), the preconditioner of H's LDL' instead, and for the rest of the
  // solver's life no LU. Throws if neither.
  void factor_fallback(bool may_ldlt);
  // T^T v on the rotation pairs of v's first num_shell entries (in place).
  static void transpose_transform(const std::vector<ShellChart::RotationBlock>& rotations,
                                  Eigen::VectorXd& v);
  int shell_slot(int row, int col) const;

  double kappa_;
  const SparseMatrix* J_ = nullptr;
  int num_shell_ = -1;
  // Shell block of J: pattern, the slot of each entry's transpose, its slots in J.
  SparseMatrix H_;
  std::vector<int> mirror_;
  std::vector<int> diagonal_slot_;  // slot of each diagonal entry of H_
  std::vector<int> j_slot_;
  std::vector<int> analyzed_outer_;             // J's column starts when j_slot_ was made
  std::vector<RotationSlots> rotation_slots_;   // per (rotation block, column of its rows)
  std::vector<std::array<int, 25>> row_slots_;  // per contact row: its 5x5 block in H_
  std::unique_ptr<LinearSolver> cholesky_;
  std::unique_ptr<LinearSolver> ldlt_;    // H's LDL', made where the LU ran out of memory
  const LinearSolver* factor_ = nullptr;  // the preconditioner's: cholesky_ or ldlt_
  CoupledLu lu_;                          // the fallback, with the rows' couplings
  bool use_lu_ = false;                   // this factorize() went to the fallback LU
  bool lu_out_of_memory_ = false;         // the LU ran out of memory once: H's LDL' instead
  int border_ = 0;
  Eigen::VectorXd border_column_, border_row_, border_solution_;  // c, d, P^-1 c
  double border_corner_ = 0, border_pivot_ = 0;                   // e, e - d^T P^-1 c
  // The current linearisation (T blocks, rows with G~ and the floored a) and the one the
  // Cholesky factor was made from (the preconditioner is reused while GMRES converges fast).
  std::vector<ShellChart::RotationBlock> rotations_, pre_rotations_;
  std::vector<ContactJacobianRow> rows_, pre_rows_;
  bool has_preconditioner_ = false;
  // The contact rows' couplings of the current linearisation and their exact elimination in the
  // preconditioner made with the current factor.
  RowCoupling coupling_;
  CoupledRows coupled_;
  int preconditioner_age_ = 0;  // factorize() calls since the Cholesky factor was made
  int last_products_ = 0;       // GMRES products of the last solve
  GmresSettings gmres_;
  ContactJacobianCounters counters_;
  // Why the last refresh of the preconditioner's factor failed (empty: it did not), for the
  // fallback LU's error if that fails too.
  std::string refresh_failure_;
};

}  // namespace si
