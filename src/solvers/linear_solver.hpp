// Sparse direct solvers for the free-dof tangent (CSC, full storage, see assembler.hpp).
// analyze() once per sparsity pattern, factorize() per Newton step, solve() per right-hand side.
// A matrix that is singular (or, for a Cholesky solver, not positive definite) makes factorize()
// throw a numerical si::Error; a near-singular one is caught by a reciprocal-condition estimate
// (pivot ratio) below kSingularRcond, since roundoff often hides an exact singularity.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/sparse.hpp"

namespace si {

// Below this pivot-ratio estimate (min/max pivot) a matrix is treated as singular: 1e-14 is about
// 50 machine epsilons. Measured on a free 6x6 spring net (tests/model): UMFPACK's estimate is
// 3.6e-16 and it does not flag the matrix itself; CHOLMOD reports "not positive definite".
// A well-supported but very thin shell has pivot ratios of order (t/L)^2 (h/L)^2, far above.
constexpr double kSingularRcond = 1e-14;

// cholmod: supernodal Cholesky (SPD); umfpack, klu: general sparse LU; ldlt: symmetric LDL'
// without pivoting (indefinite allowed, ldlt_solver.hpp).
enum class LinearSolverKind { kCholmod, kUmfpack, kKlu, kLdlt };

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual LinearSolverKind kind() const = 0;
  virtual std::string name() const = 0;  // for messages: "cholmod", "umfpack", "klu"
  // True if the solver needs a symmetric positive-definite matrix (reads the lower triangle only).
  virtual bool needs_spd() const = 0;
  virtual void analyze(const SparseMatrix& A) = 0;
  // Same pattern as at analyze(). Throws a numerical error if A is singular / not SPD.
  virtual void factorize(const SparseMatrix& A) = 0;
  virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  // X = A^-1 B for several right-hand sides at once (a supernodal solver blocks them: BLAS-3).
  virtual Eigen::MatrixXd solve_columns(const Eigen::MatrixXd& B) const;
  // Reciprocal condition estimate of the last factorization (ratio of extreme pivots).
  virtual double rcond() const = 0;
  // The last analyze() or factorize() failed for lack of memory, not for the matrix: a caller
  // choosing between routes need not try this one again at the same size.
  virtual bool out_of_memory() const { return false; }
};

std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind);

// Makes a solver: where a caller needs fresh ones of a kind it is given (e.g. a fallback LU).
using LinearSolverFactory = std::function<std::unique_ptr<LinearSolver>()>;

// The message every solver uses when the matrix turns out singular.
std::string singular_matrix_message(const std::string& solver, double rcond);

}  // namespace si
