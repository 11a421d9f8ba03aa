// The inertia of a sparse symmetric matrix by an LDL^T factorization and Sylvester's law of
// inertia (Sylvester 1852; Golub & Van Loan 2013, Thm 8.1.17): P (K - sigma I) P' = L D L' with L
// unit lower triangular is a congruence, so K - sigma I and the diagonal D have the same numbers
// of negative, zero and positive entries, i.e. D's negative pivots count the eigenvalues of K
// below sigma. The factorization is Eigen's SimplicialLDLT (AMD ordering, no pivoting for
// stability): for an indefinite matrix it exists when no leading pivot vanishes and then gives the
// exact count up to the rounding of the pivots' signs, which is the practice of structural codes
// (the "negative pivots" of a stiffness factorization).
//
// Zero pivots: a pivot with |d| <= zero_pivot_tolerance * max|d| counts as zero (neither negative
// nor positive: the matrix is numerically singular there). A pivot that is exactly zero stops the
// factorization; factorize() then refactors at sigma -+ delta, delta = zero_pivot_tolerance *
// max|K_ii|, and counts negative = #(eigenvalues < sigma - delta) and zero = #(eigenvalues in
// [sigma - delta, sigma + delta]) from the two shifted factorizations (Sylvester again); the
// factorization kept for solves is the one at sigma - delta (shift() says so).
// Docs: docs/theory/continuation.md, "Stability".
#pragma once

#include <functional>
#include <memory>

#include <Eigen/SparseCholesky>

#include "continuation/sparse_matrix.hpp"

namespace si::cont {

struct Inertia {
  int negative = 0;
  int zero = 0;
  int positive = 0;
};

// A factorization of K - sigma I that knows its inertia and solves with it: what the stability
// tools need (lowest_eigenpairs.hpp, stability_analysis.hpp). SparseLdlt below is the default;
// cholmod_factorization.hpp is the fast one for large problems.
class SymmetricFactorization {
 public:
  virtual ~SymmetricFactorization() = default;
  // Factor K - sigma I (K symmetric, both triangles stored). false when no factorization could
  // be made.
  virtual bool factorize(const SparseMatrix& K, double sigma) = 0;
  // The inertia of K - sigma I (for the sigma given to factorize()).
  virtual const Inertia& inertia() const = 0;
  // The shift of the factorization kept for solves (sigma, unless a zero pivot moved it).
  virtual double shift() const = 0;
  virtual Eigen::Index rows() const = 0;
  // (K - shift() I) out = in. false if not factored.
  virtual bool solve(const double* in, double* out) const = 0;
  bool solve(Vector& b) const;
};

// Makes a fresh factorization (for the lower shifts of lowest_eigenpairs).
using FactorizationFactory = std::function<std::unique_ptr<SymmetricFactorization>()>;

class SparseLdlt final : public SymmetricFactorization {
 public:
  explicit SparseLdlt(double zero_pivot_tolerance = 1e-12)
      : zero_pivot_tolerance_(zero_pivot_tolerance) {}

  // Only K's lower triangle is read. false when no factorization could be made (not even at the
  // shifted sigma: a structurally singular K).
  bool factorize(const SparseMatrix& K, double sigma) override;
  const Inertia& inertia() const override { return inertia_; }
  // sigma, or sigma - delta after a zero pivot.
  double shift() const override { return shift_; }
  Eigen::Index rows() const override { return rows_; }
  bool solve(const double* in, double* out) const override;
  using SymmetricFactorization::solve;

 private:
  bool factor_at(const SparseMatrix& K, double sigma);
  Inertia pivot_inertia() const;

  double zero_pivot_tolerance_;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt_;
  bool factored_ = false;
  Eigen::Index rows_ = 0;
  double shift_ = 0.0;
  Inertia inertia_;
};

}  // namespace si::cont
