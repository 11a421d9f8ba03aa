#include "continuation/cholmod_factorization.hpp"

#include <Eigen/CholmodSupport>

namespace si::cont {

struct CholmodFirstFactorization::Impl {
  // CHOLMOD prints "matrix not positive definite" to stderr when the LL' stops: here that is
  // an answer (the LDL' counts), not a warning for a run's output.
  explicit Impl(double tolerance) : ldlt(tolerance) { llt.cholmod().print = 0; }
  Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
  SparseLdlt ldlt;
};

CholmodFirstFactorization::CholmodFirstFactorization(double zero_pivot_tolerance)
    : impl_(std::make_unique<Impl>(zero_pivot_tolerance)) {}

CholmodFirstFactorization::~CholmodFirstFactorization() = default;

bool CholmodFirstFactorization::factorize(const SparseMatrix& K, double sigma) {
  rows_ = K.rows();
  factored_ = false;
  cholesky_ = false;
  if (rows_ == 0) {
    inertia_ = {};
    shift_ = sigma;
    factored_ = true;
    return true;
  }
  impl_->llt.setShift(-sigma);
  impl_->llt.compute(K);
  if (impl_->llt.info() == Eigen::Success) {
    inertia_ = {0, 0, static_cast<int>(rows_)};
    shift_ = sigma;
    cholesky_ = factored_ = true;
    return true;
  }
  if (!impl_->ldlt.factorize(K, sigma)) return false;
  inertia_ = impl_->ldlt.inertia();
  shift_ = impl_->ldlt.shift();
  factored_ = true;
  return true;
}

bool CholmodFirstFactorization::solve(const double* in, double* out) const {
  if (!factored_) return false;
  if (!cholesky_) return impl_->ldlt.solve(in, out);
  const Eigen::Map<const Vector> b(in, rows_);
  Eigen::Map<Vector> x(out, rows_);
  x = impl_->llt.solve(b);
  return x.allFinite();
}

FactorizationFactory cholmod_first_factorization(double zero_pivot_tolerance) {
  return [zero_pivot_tolerance] {
    return std::make_unique<CholmodFirstFactorization>(zero_pivot_tolerance);
  };
}

}  // namespace si::cont
