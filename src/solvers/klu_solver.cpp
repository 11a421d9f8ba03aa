#include "solvers/klu_solver.hpp"

#include <Eigen/KLUSupport>

#include "core/error.hpp"

namespace si {

// Eigen's wrapper does not expose klu_rcond (the ratio of extreme pivots of U), so derive.
struct KluSolver::Impl : Eigen::KLU<SparseMatrix> {
  double rcond() {
    if (!m_numeric || !klu_rcond(m_symbolic, m_numeric, &m_common)) return 0.0;
    return m_common.rcond;
  }
  bool analyzed = false;
};

KluSolver::KluSolver() : impl_(std::make_unique<Impl>()) {}
KluSolver::~KluSolver() = default;

void KluSolver::analyze(const SparseMatrix& A) {
  impl_->analyzePattern(A);
  if (impl_->info() != Eigen::Success) throw_numerical("KLU symbolic analysis failed");
  impl_->analyzed = true;
}

void KluSolver::factorize(const SparseMatrix& A) {
  if (!impl_->analyzed) analyze(A);
  impl_->factorize(A);
  rcond_ = impl_->info() == Eigen::Success ? impl_->rcond() : 0.0;
  if (impl_->info() != Eigen::Success || !(rcond_ >= kSingularRcond))
    throw_numerical(singular_matrix_message("KLU", rcond_));
}

Eigen::VectorXd KluSolver::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = impl_->solve(b);
  if (impl_->info() != Eigen::Success) throw_numerical("KLU solve failed");
  return x;
}

}  // namespace si
