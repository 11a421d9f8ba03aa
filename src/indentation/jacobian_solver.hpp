// The linear solver of the indentation problem's Jacobian, chosen once per problem: GMRES
// preconditioned by a Cholesky factorization of the condensed shell block
// (contact_jacobian_solver.hpp), which needs every contact row condensable (rows on one node's
// dofs: the nodal gaps, with or without a thin layer) or a border (a power law's alpha), or a
// direct sparse LU of the whole Jacobian (unsymmetric: UMFPACK or KLU), which takes anything
// (weighted gaps).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "continuation/penalized_stability.hpp"
#include "core/sparse.hpp"
#include "indentation/contact_jacobian_solver.hpp"
#include "indentation/row_coupling.hpp"
#include "model/shell_chart.hpp"
#include "solvers/linear_solver.hpp"

namespace si {

// kPreconditionedKrylov falls back to UMFPACK for problems whose rows do not condense.
enum class JacobianSolverKind { kPreconditionedKrylov, kUmfpack, kKlu };

// The stability analysis's penalised shell factor (continuation/penalized_stability.hpp).
struct PenalizedShell {
  cont::PenalizedSolve solve;  // P^-1 on the shell block, in chart coordinates
  SparseMatrix gradients;      // the penalised rows' G~_i^T: rows x shell unknowns
};

class JacobianSolver {
 public:
  virtual ~JacobianSolver() = default;
  // Whether factorize() wants the condensed rows (ContactTerm::add_jacobian).
  virtual bool wants_condensed_rows() const = 0;
  // The Jacobian's pattern changed (candidates added): a direct solver analyses it anew.
  virtual void pattern_changed() {}
  // Forgets what one factorization hands the next (a reused preconditioner, an LU's symbolic
  // analysis, which UMFPACK makes from the values it first sees): the solves that follow are a
  // new solver's, bit for bit (cont::Problem::reset_solver_caches).
  virtual void reset() = 0;
  // J: the num_shell shell rows and columns first, then the terms' (in `rows` for a Krylov
  // solver), the last `border` of them bordering unknowns (ContactTerm::borders); `coupling`:
  // the contact rows' couplings beside J (row_coupling.hpp), part of the matrix solved. Throws
  // a numerical si::Error if it cannot be factored.
  virtual void factorize(const SparseMatrix& J, int num_shell,
                         const std::vector<ShellChart::RotationBlock>& rotations,
                         const std::vector<ContactJacobianRow>& rows, int border,
                         RowCoupling coupling) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& rhs) = 0;
  // The Krylov solver's work (zero for a direct LU).
  virtual ContactJacobianCounters counters() const { return {}; }
  // Refactors the preconditioner at the last factorize()'s linearisation as P = sym(T^T A) +
  // rho sum_i G~_i G~_i^T over the contact rows `rows` (indices among the terms' rows; rho =
  // kappa / the condensation floor), the other rows uncondensed, and keeps it for the solves that
  // follow: a preconditioner like any other. Its solve is valid until the next factorize().
  // Nothing if there is no such factor to make (a direct LU; this linearisation on the fallback
  // LU or with a border) or P is not positive definite; the solver is then as factorize() left it.
  virtual std::optional<PenalizedShell> penalized_shell(const std::vector<int>& /*rows*/) {
    return std::nullopt;
  }
};

// condensable: whether every part of the problem has condensable rows or borders. kappa: the
// problem's stiffness scale (N/mm); krylov_tolerance: GMRES's relative residual.
std::unique_ptr<JacobianSolver> make_jacobian_solver(JacobianSolverKind kind, bool condensable,
                                                     double kappa, double krylov_tolerance);

}  // namespace si
