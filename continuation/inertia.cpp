#include "continuation/inertia.hpp"

#include <algorithm>
#include <cmath>

namespace si::cont {
namespace {

double max_abs_diagonal(const SparseMatrix& K) {
  double m = 0.0;
  for (Eigen::Index j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (it.row() == it.col()) m = std::max(m, std::abs(it.value()));
  return m;
}

}  // namespace

bool SparseLdlt::factor_at(const SparseMatrix& K, double sigma) {
  ldlt_.setShift(-sigma);
  ldlt_.factorize(K);
  return ldlt_.info() == Eigen::Success && ldlt_.vectorD().allFinite();
}

Inertia SparseLdlt::pivot_inertia() const {
  const Vector& d = ldlt_.vectorD();
  const double tol = zero_pivot_tolerance_ * (d.size() ? d.cwiseAbs().maxCoeff() : 0.0);
  Inertia in;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (std::abs(d(i)) <= tol)
      ++in.zero;
    else if (d(i) < 0.0)
      ++in.negative;
    else
      ++in.positive;
  }
  return in;
}

bool SparseLdlt::factorize(const SparseMatrix& K, double sigma) {
  rows_ = K.rows();
  factored_ = false;
  // The ordering and symbolic analysis, once for the (up to three) numeric factorizations below.
  ldlt_.analyzePattern(K);
  if (factor_at(K, sigma)) {
    shift_ = sigma;
    inertia_ = pivot_inertia();
    factored_ = true;
    return true;
  }
  // An exactly zero pivot: count through two shifted factorizations (see the header).
  const double delta = zero_pivot_tolerance_ * std::max(max_abs_diagonal(K), 1e-300);
  if (!factor_at(K, sigma + delta)) return false;
  const int below_plus = pivot_inertia().negative;
  if (!factor_at(K, sigma - delta)) return false;
  const Inertia below = pivot_inertia();
  inertia_.negative = below.negative;
  inertia_.zero = below_plus - below.negative;
  inertia_.positive = static_cast<int>(rows_) - inertia_.negative - inertia_.zero;
  shift_ = sigma - delta;
  factored_ = true;
  return true;
}

bool SymmetricFactorization::solve(Vector& b) const {
  if (b.size() != rows()) return false;
  const Vector in = b;
  return solve(in.data(), b.data());
}

bool SparseLdlt::solve(const double* in, double* out) const {
  if (!factored_) return false;
  Eigen::Map<const Vector> x(in, rows_);
  Eigen::Map<Vector> y(out, rows_);
  y = ldlt_.solve(x);
  return y.allFinite();
}

}  // namespace si::cont
