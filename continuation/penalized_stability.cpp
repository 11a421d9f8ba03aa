#include "continuation/penalized_stability.hpp"

#include <Spectra/SymEigsSolver.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <stdexcept>

#include "continuation/spectra_lanczos.hpp"

namespace si::cont {
namespace {

// Pi = I - A'(AA')^-1 A, the orthogonal projector on null(A); the identity without constraints.
class NullSpaceProjector {
 public:
  explicit NullSpaceProjector(const SparseMatrix& A) : A_(A) {
    if (A.rows() > 0) gram_.compute(SparseMatrix(A * SparseMatrix(A.transpose())));
  }
  bool ok() const { return A_.rows() == 0 || gram_.info() == Eigen::Success; }
  void apply(Vector& v) const {
    if (A_.rows() > 0) v -= A_.transpose() * gram_.solve(A_ * v);
  }

 private:
  const SparseMatrix& A_;
  Eigen::SimplicialLDLT<SparseMatrix> gram_;
};

// Spectra's operator interface for Pi P^-1 Pi.
class ProjectedInverse {
 public:
  using Scalar = double;
  ProjectedInverse(const PenalizedSolve& solve, const NullSpaceProjector& pi, Eigen::Index n)
      : solve_(solve), pi_(pi), n_(n) {}
  Eigen::Index rows() const { return n_; }
  Eigen::Index cols() const { return n_; }
  void perform_op(const double* in, double* out) const {
    Vector x = Eigen::Map<const Vector>(in, n_);
    pi_.apply(x);
    Vector y;
    solve_(x, y);
    if (y.size() != n_ || !y.allFinite()) throw std::runtime_error("penalised solve failed");
    pi_.apply(y);
    Eigen::Map<Vector>(out, n_) = y;
  }

 private:
  const PenalizedSolve& solve_;
  const NullSpaceProjector& pi_;
  Eigen::Index n_;
};

}  // namespace

bool stability_from_penalized(const PenalizedSolve& solve, const SparseMatrix& A, Eigen::Index n,
                              int modes, const EigenOptions& options, Stability& out) {
  const Eigen::Index free = n - A.rows();
  const int k = static_cast<int>(std::min<Eigen::Index>(modes, free));
  if (k < 1 || free <= options.dense_size + 1) return false;
  const NullSpaceProjector pi(A);
  if (!pi.ok()) return false;
  ProjectedInverse op(solve, pi, n);
  // range(A') is in the operator's kernel (theta = 0): the Krylov space needs no more room than
  // for Z'KZ itself.
  Spectra::SymEigsSolver<ProjectedInverse> lanczos(op, k, lanczos_basis(free, k, options));
  if (!run_lanczos(lanczos, Spectra::SortRule::LargestAlge, Spectra::SortRule::LargestAlge,
                   options))
    return false;
  const Vector theta = lanczos.eigenvalues();
  // P positive definite makes Pi P^-1 Pi positive semidefinite: a theta <= 0 among the largest is
  // a failed solve, not an eigenvalue.
  if (theta.size() != k || !theta.allFinite() || theta.minCoeff() <= 0.0) return false;
  Matrix vectors = lanczos.eigenvectors();
  for (Eigen::Index c = 0; c < vectors.cols(); ++c) {
    Vector v = vectors.col(c);
    pi.apply(v);  // in null(A) to round-off already; exactly so for the multipliers' part
    vectors.col(c) = v;
  }
  Eigenpairs pairs;
  normalise_eigenpairs(theta.cwiseInverse(), vectors, pairs);
  out.negative = 0;
  out.zero = 0;
  out.eigenvalues = pairs.values;
  out.modes.clear();
  for (Eigen::Index c = 0; c < pairs.vectors.cols(); ++c)
    out.modes.emplace_back(pairs.vectors.col(c));
  return true;
}

}  // namespace si::cont
