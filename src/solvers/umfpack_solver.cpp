#include "solvers/umfpack_solver.hpp"

#include <Eigen/UmfPackSupport>

#include "core/error.hpp"

namespace si {

// Eigen's wrapper does not expose UMFPACK's Info array, which holds the rcond estimate.
struct UmfpackSolver::Impl : Eigen::UmfPackLU<SparseMatrix> {
  double rcond() const { return this->m_umfpackInfo[UMFPACK_RCOND]; }
  bool analyzed = false;
};

// No iterative refinement: it costs two or three extra solves and residuals per solve (12 % of
// a nonlinear indentation path, perf), and every caller is a Newton iteration or a well-
// conditioned linear solve whose residual is checked by the caller.
// METIS ordering: 80 ms instead of 87 ms (AMD) per factorization of the paper cap's contact
// Jacobian at 1e4 unknowns (docs/performance.md).
UmfpackSolver::UmfpackSolver() : impl_(std::make_unique<Impl>()) {
  impl_->umfpackControl()[UMFPACK_IRSTEP] = 0;
  impl_->umfpackControl()[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
}
UmfpackSolver::~UmfpackSolver() = default;

void UmfpackSolver::analyze(const SparseMatrix& A) {
  impl_->analyzePattern(A);
  if (impl_->info() != Eigen::Success) throw_numerical("UMFPACK symbolic analysis failed");
  impl_->analyzed = true;
}

void UmfpackSolver::factorize(const SparseMatrix& A) {
  if (!impl_->analyzed) analyze(A);
  impl_->factorize(A);
  rcond_ = impl_->rcond();
  // UMFPACK_WARNING_singular_matrix makes Eigen report NumericalIssue.
  if (impl_->info() != Eigen::Success || !(rcond_ >= kSingularRcond))
    throw_numerical(singular_matrix_message("UMFPACK", rcond_));
}

Eigen::VectorXd UmfpackSolver::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = impl_->solve(b);
  if (impl_->info() != Eigen::Success) throw_numerical("UMFPACK solve failed");
  return x;
}

}  // namespace si
