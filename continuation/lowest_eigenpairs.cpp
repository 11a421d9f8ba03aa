#include "continuation/lowest_eigenpairs.hpp"

#include <Spectra/SymEigsShiftSolver.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>

#include "continuation/spectra_lanczos.hpp"

namespace si::cont {
namespace {

// The relative distance from an eigenvalue at which shift-invert is well conditioned: the modes'
// error is then about the factorization's round-off over it, 1e-16 / 1e-8.
constexpr double kClearShift = 1e-8;

// Spectra's operator interface for (K - sigma I)^-1 with a factorization made elsewhere, so that
// the inertia's factorization is reused (Spectra's own SparseSymShiftSolve would refactor).
class ShiftSolve {
 public:
  using Scalar = double;
  explicit ShiftSolve(const SymmetricFactorization& factorization)
      : factorization_(factorization) {}
  Eigen::Index rows() const { return factorization_.rows(); }
  Eigen::Index cols() const { return factorization_.rows(); }
  void set_shift(double) {}  // the factorization carries its own shift
  void perform_op(const double* in, double* out) const {
    if (!factorization_.solve(in, out)) throw std::runtime_error("shift-invert solve failed");
  }

 private:
  const SymmetricFactorization& factorization_;
};

void dense_lowest(const SparseMatrix& K, int k, Eigenpairs& out) {
  const Eigen::SelfAdjointEigenSolver<Matrix> dense{Matrix(K)};
  normalise_eigenpairs(dense.eigenvalues().head(k), dense.eigenvectors().leftCols(k), out);
}

// The k eigenpairs nearest the factorization's shift. false if Lanczos did not converge.
bool nearest(const SymmetricFactorization& factorization, int k, const EigenOptions& options,
             Vector& values, Matrix& vectors) {
  const auto n = factorization.rows();
  ShiftSolve op(factorization);
  Spectra::SymEigsShiftSolver<ShiftSolve> solver(op, k, lanczos_basis(n, k, options),
                                                 factorization.shift());
  if (!run_lanczos(solver, Spectra::SortRule::LargestMagn, Spectra::SortRule::SmallestAlge,
                   options))
    return false;
  values = solver.eigenvalues();
  vectors = solver.eigenvectors();
  return values.size() == k && values.allFinite();
}

}  // namespace

void normalise_eigenpairs(Vector values, Matrix vectors, Eigenpairs& out) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(values.size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&values](Eigen::Index a, Eigen::Index b) { return values(a) < values(b); });
  out.values.resize(values.size());
  out.vectors.resize(vectors.rows(), vectors.cols());
  for (std::size_t j = 0; j < order.size(); ++j) {
    const auto c = static_cast<Eigen::Index>(j);
    Vector v = vectors.col(order[j]);
    Eigen::Index imax = 0;
    v.cwiseAbs().maxCoeff(&imax);
    if (v(imax) < 0.0) v = -v;
    out.values(c) = values(order[j]);
    out.vectors.col(c) = v / v.norm();
  }
}

bool lowest_eigenpairs(const SparseMatrix& K, int k, const SymmetricFactorization& factorization,
                       const EigenOptions& options, Eigenpairs& out,
                       const FactorizationFactory& make) {
  const auto n = static_cast<int>(K.rows());
  k = std::min(k, n);
  if (k <= 0) {
    out = {};
    return true;
  }
  if (n <= std::max(options.dense_size, k + 1)) {
    dense_lowest(K, k, out);
    return true;
  }
  const SymmetricFactorization* current = &factorization;
  std::unique_ptr<SymmetricFactorization> shifted = make ? make() : std::make_unique<SparseLdlt>();
  if (factorization.inertia().zero > 0) {
    // The shift sits on an eigenvalue to round-off (a located critical point: the event's own
    // point). Shift-invert there divides by a pivot of round-off size in a factorization without
    // pivoting, and the modes lose accuracy (measured: 8e-4 rad on the beam on a foundation);
    // a shift clear of it by kClearShift of K's scale is well conditioned, and its nearest
    // eigenvalues are still the lowest ones once every one below it is found (the loop below).
    const double scale = K.diagonal().cwiseAbs().maxCoeff();
    if (!shifted->factorize(K, factorization.shift() - kClearShift * std::max(scale, 1e-300)))
      return false;
    current = shifted.get();
  }
  for (int attempt = 0; attempt <= options.max_shifts; ++attempt) {
    Vector values;
    Matrix vectors;
    if (!nearest(*current, k, options, values, vectors)) return false;
    const double sigma = current->shift();
    const int found_below = static_cast<int>((values.array() < sigma).count());
    if (found_below >= current->inertia().negative) {
      normalise_eigenpairs(values, vectors, out);
      return true;
    }
    const double lowest = values.minCoeff();
    const double drop = std::max({sigma - lowest, values.maxCoeff() - lowest, 1e-300});
    if (!shifted->factorize(K, lowest - drop)) return false;
    current = shifted.get();
  }
  return false;
}

}  // namespace si::cont
