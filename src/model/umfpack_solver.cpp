#include "model/umfpack_solver.hpp"

#include <Eigen/UmfPackSupport>

#include "core/error.hpp"

namespace si {

// Eigen's wrapper does not expose UMFPACK's Info array, which holds the rcond estimate.
struct UmfpackSolver::Impl : Eigen::UmfPackLU<SparseMatrix> {
  double rcond() const { return this->m_umfpackInfo[UMFPACK_RCOND]; }
  bool analyzed = false;
};

UmfpackSolver::UmfpackSolver() : impl_(std::make_unique<Impl>()) {}
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
