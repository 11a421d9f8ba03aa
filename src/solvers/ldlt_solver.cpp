#include "solvers/ldlt_solver.hpp"

#include <new>

#include <Eigen/SparseCholesky>

#include "core/error.hpp"

namespace si {

struct LdltSolver::Impl {
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt;
  bool analyzed = false;
};

LdltSolver::LdltSolver() : impl_(std::make_unique<Impl>()) {}
LdltSolver::~LdltSolver() = default;

void LdltSolver::analyze(const SparseMatrix& A) {
  out_of_memory_ = false;
  try {
    impl_->ldlt.analyzePattern(A);
  } catch (const std::bad_alloc&) {
    out_of_memory_ = true;
    throw_numerical("LDL': out of memory for the analysis of a matrix of " +
                    std::to_string(A.rows()) + " unknowns");
  }
  impl_->analyzed = true;
}

void LdltSolver::factorize(const SparseMatrix& A) {
  if (!impl_->analyzed) analyze(A);
  out_of_memory_ = false;
  rcond_ = 0;
  negative_pivots_ = 0;
  try {
    impl_->ldlt.factorize(A);
  } catch (const std::bad_alloc&) {
    out_of_memory_ = true;
    throw_numerical("LDL': out of memory for the factor of a matrix of " +
                    std::to_string(A.rows()) + " unknowns, " + std::to_string(A.nonZeros()) +
                    " nonzeros");
  }
  if (impl_->ldlt.info() != Eigen::Success)
    throw_numerical(singular_matrix_message("LDL': a zero pivot", 0.0));
  const Eigen::VectorXd& d = impl_->ldlt.vectorD();
  const Eigen::VectorXd magnitude = d.cwiseAbs();
  rcond_ = d.size() == 0 ? 1.0 : magnitude.minCoeff() / magnitude.maxCoeff();
  negative_pivots_ = static_cast<int>((d.array() < 0.0).count());
  if (!(rcond_ >= kSingularRcond)) throw_numerical(singular_matrix_message("LDL'", rcond_));
}

Eigen::VectorXd LdltSolver::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = impl_->ldlt.solve(b);
  if (impl_->ldlt.info() != Eigen::Success) throw_numerical("LDL' solve failed");
  return x;
}

}  // namespace si
