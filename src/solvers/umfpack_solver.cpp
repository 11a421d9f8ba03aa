#include "solvers/umfpack_solver.hpp"

#include <Eigen/UmfPackSupport>

#include "core/error.hpp"

namespace si {

// Eigen's wrapper does not expose UMFPACK's Info array, which holds the rcond estimate.
struct UmfpackSolver::Impl : Eigen::UmfPackLU<SparseMatrix> {
  double rcond() const { return this->m_umfpackInfo[UMFPACK_RCOND]; }
  // UMFPACK's status of the last symbolic or numeric factorization (UMFPACK_OK, a warning > 0,
  // an error < 0).
  int status() const { return static_cast<int>(this->m_umfpackInfo[UMFPACK_STATUS]); }
  bool analyzed = false;
};

// No iterative refinement: it costs two or three extra solves and residuals per solve (12 % of
// a nonlinear indentation path, perf), and every caller is a Newton iteration or a well-
// conditioned linear solve whose residual is checked by the caller.
// METIS ordering: 80 ms instead of 87 ms (AMD) per factorization of the paper cap's contact
// Jacobian at 1e4 unknowns (docs/performance.md).
namespace {

// UMFPACK's error, said: a lack of memory (the LU of a 1e6-unknown shell needs more than the
// Cholesky factor it stands in for) is not a singular model.
std::string status_text(int status, const SparseMatrix& A) {
  const std::string size =
      std::to_string(A.rows()) + " unknowns, " + std::to_string(A.nonZeros()) + " nonzeros";
  if (status == UMFPACK_ERROR_out_of_memory) return ": out of memory (" + size + ")";
  return " (UMFPACK status " + std::to_string(status) + ", " + size + ")";
}

}  // namespace

UmfpackSolver::UmfpackSolver() : impl_(std::make_unique<Impl>()) {
  impl_->umfpackControl()[UMFPACK_IRSTEP] = 0;
  impl_->umfpackControl()[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
}
UmfpackSolver::~UmfpackSolver() = default;

void UmfpackSolver::analyze(const SparseMatrix& A) {
  impl_->analyzePattern(A);
  out_of_memory_ = impl_->status() == UMFPACK_ERROR_out_of_memory;
  if (impl_->info() != Eigen::Success)
    throw_numerical("UMFPACK symbolic analysis failed" + status_text(impl_->status(), A));
  impl_->analyzed = true;
}

void UmfpackSolver::factorize(const SparseMatrix& A) {
  if (!impl_->analyzed) analyze(A);
  impl_->factorize(A);
  rcond_ = impl_->rcond();
  // UMFPACK_WARNING_singular_matrix makes Eigen report NumericalIssue; so does an error.
  const int status = impl_->status();
  out_of_memory_ = status == UMFPACK_ERROR_out_of_memory;
  if (status < 0) throw_numerical("UMFPACK: the factorization failed" + status_text(status, A));
  if (impl_->info() != Eigen::Success || !(rcond_ >= kSingularRcond))
    throw_numerical(singular_matrix_message("UMFPACK", rcond_));
}

Eigen::VectorXd UmfpackSolver::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = impl_->solve(b);
  if (impl_->info() != Eigen::Success) throw_numerical("UMFPACK solve failed");
  return x;
}

}  // namespace si
