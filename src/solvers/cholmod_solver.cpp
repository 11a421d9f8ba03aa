#include "solvers/cholmod_solver.hpp"

#include <omp.h>

#include <Eigen/CholmodSupport>

#include "core/error.hpp"

namespace si {

// Eigen's wrapper does not expose the factor; cholmod_rcond needs it.
struct CholmodSolver::Impl : Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> {
  Impl() { this->cholmod().print = 0; }  // we report failures ourselves
  double rcond() { return cholmod_rcond(this->m_cholmodFactor, &this->cholmod()); }
  // The matrix's column whose pivot failed: L->minor is in the fill-reducing order (the first
  // column of its supernode), L->Perm maps it back. -1 if the factor does not say.
  long failed_column() const {
    const cholmod_factor* L = this->m_cholmodFactor;
    if (L == nullptr || L->Perm == nullptr || L->minor >= L->n) return -1;
    return static_cast<const int*>(L->Perm)[L->minor];
  }
  bool analyzed = false;
};

// CHOLMOD 3 (SuiteSparse 5) runs parts of its supernodal factorization in OpenMP teams of a
// compile-time size (CHOLMOD_OMP_NUM_THREADS = 4), whatever OMP_NUM_THREADS says: on a 2-core
// machine the oversubscribed team and its spin-waiting cost 40 % of a nonlinear indentation path
// (11.2 s -> 6.9 s for the 1e4-unknown cap to 2 mm with the team made serial). With
// max-active-levels 0 every parallel region inside runs on the calling thread; the previous value
// is restored on exit (the element assembly keeps its threads).
class SerialOpenMpRegion {
 public:
  SerialOpenMpRegion() : levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }
  ~SerialOpenMpRegion() { omp_set_max_active_levels(levels_); }
  SerialOpenMpRegion(const SerialOpenMpRegion&) = delete;
  SerialOpenMpRegion& operator=(const SerialOpenMpRegion&) = delete;

 private:
  int levels_;
};

CholmodSolver::CholmodSolver() : impl_(std::make_unique<Impl>()) {}
CholmodSolver::~CholmodSolver() = default;

void CholmodSolver::analyze(const SparseMatrix& A) {
  const SerialOpenMpRegion serial;
  impl_->analyzePattern(A);
  if (impl_->info() != Eigen::Success) throw_numerical("CHOLMOD symbolic analysis failed");
  impl_->analyzed = true;
}

void CholmodSolver::factorize(const SparseMatrix& A) {
  if (!impl_->analyzed) analyze(A);
  const SerialOpenMpRegion serial;
  impl_->factorize(A);
  const int status = impl_->cholmod().status;
  out_of_memory_ = status == CHOLMOD_OUT_OF_MEMORY || status == CHOLMOD_TOO_LARGE;
  if (impl_->info() != Eigen::Success) {
    rcond_ = 0;
    throw_numerical(failure_message(A));
  }
  rcond_ = impl_->rcond();
  if (!(rcond_ >= kSingularRcond)) throw_numerical(singular_matrix_message("CHOLMOD", rcond_));
}

// Why the factorization failed, from CHOLMOD's status: a pivot that is not positive (with its
// column, which names the node whose dof it is) or a lack of memory (a 1e6-unknown shell's factor
// is gigabytes), which no change of the model would cure and which must not read as one.
std::string CholmodSolver::failure_message(const SparseMatrix& A) const {
  const int status = impl_->cholmod().status;
  const std::string size =
      std::to_string(A.rows()) + " unknowns, " + std::to_string(A.nonZeros()) + " nonzeros";
  if (status == CHOLMOD_OUT_OF_MEMORY || status == CHOLMOD_TOO_LARGE)
    return "CHOLMOD: out of memory for the factor of a matrix of " + size;
  if (status == CHOLMOD_NOT_POSDEF)
    return singular_matrix_message("CHOLMOD: not positive definite, at column " +
                                       std::to_string(impl_->failed_column()) + " of " +
                                       std::to_string(A.rows()) + " (or one factored with it)",
                                   0.0);
  return "CHOLMOD: the factorization failed (status " + std::to_string(status) + ", " + size + ")";
}

Eigen::VectorXd CholmodSolver::solve(const Eigen::VectorXd& b) const {
  const SerialOpenMpRegion serial;
  Eigen::VectorXd x = impl_->solve(b);
  if (impl_->info() != Eigen::Success) throw_numerical("CHOLMOD solve failed");
  return x;
}

Eigen::MatrixXd CholmodSolver::solve_columns(const Eigen::MatrixXd& B) const {
  const SerialOpenMpRegion serial;
  Eigen::MatrixXd X = impl_->solve(B);  // one cholmod_solve over all columns
  if (impl_->info() != Eigen::Success) throw_numerical("CHOLMOD solve failed");
  return X;
}

}  // namespace si
