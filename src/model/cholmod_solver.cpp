#include "model/cholmod_solver.hpp"

#include <Eigen/CholmodSupport>

#include "core/error.hpp"

namespace si {

// Eigen's wrapper does not expose the factor; cholmod_rcond needs it.
struct CholmodSolver::Impl : Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
  Impl() { this->cholmod().print = 0; }  // we report failures ourselves
  double rcond() { return cholmod_rcond(this->m_cholmodFactor, &this->cholmod()); }
  bool analyzed = false;
};

CholmodSolver::CholmodSolver() : impl_(std::make_unique<Impl>()) {}
CholmodSolver::~CholmodSolver() = default;

void CholmodSolver::analyze(const SparseMatrix& A) {
  impl_->analyzePattern(A);
  if (impl_->info() != Eigen::Success) throw_numerical("CHOLMOD symbolic analysis failed");
  impl_->analyzed = true;
}

void CholmodSolver::factorize(const SparseMatrix& A) {
  if (!impl_->analyzed) analyze(A);
  impl_->factorize(A);
  if (impl_->info() != Eigen::Success) {
    rcond_ = 0;
    throw_numerical(singular_matrix_message("CHOLMOD: not positive definite", rcond_));
  }
  rcond_ = impl_->rcond();
  if (!(rcond_ >= kSingularRcond)) throw_numerical(singular_matrix_message("CHOLMOD", rcond_));
}

Eigen::VectorXd CholmodSolver::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = impl_->solve(b);
  if (impl_->info() != Eigen::Success) throw_numerical("CHOLMOD solve failed");
  return x;
}

}  // namespace si
