// The algebraically lowest k eigenpairs of a sparse symmetric matrix K, by shift-invert Lanczos
// (Spectra's SymEigsShiftSolver: the implicitly restarted Lanczos method of ARPACK on
// (K - sigma I)^-1, whose largest eigenvalues 1/(lambda - sigma) are those of K nearest sigma;
// Ericsson & Ruhe 1980, Grimes, Lewis & Simon 1994). The operator is applied with the
// factorization already made for the inertia (a SymmetricFactorization).
//
// Nearest sigma is not lowest: the k eigenvalues nearest sigma are the k lowest exactly when they
// include every eigenvalue below sigma, whose number the factorization's inertia gives (Sylvester).
// So: Lanczos at the given factorization's shift; if fewer eigenvalues below sigma were found than
// the inertia counts, a lower shift (below the lowest found, by at least the spread of those
// found) is factored and Lanczos repeated, at most max_shifts times. At a stable point (no
// negative eigenvalue, shift 0) one factorization serves both the count and the modes.
// Matrices of at most dense_size rows are solved densely (Eigen's SelfAdjointEigenSolver).
#pragma once

#include "continuation/inertia.hpp"

namespace si::cont {

struct EigenOptions {
  int dense_size = 32;
  // Spectra's convergence test on the Ritz values theta of (K - sigma I)^-1: |residual| <=
  // tolerance * |theta|. The eigenvalue error is of the order of the residual squared over the
  // gap (symmetric case), far below it. 1e-12 took as many solves as 1e-10 on the paper's cap.
  double tolerance = 1e-10;
  // The Lanczos basis: max(2k + 1, subspace) vectors. 10 instead of 20 took 13 instead of 21
  // shift-invert solves per point for the lowest eigenvalue along the paper's cap (same values
  // to the printed 12 digits).
  int subspace = 10;
  int max_iterations = 1000;
  int max_shifts = 8;
};

struct Eigenpairs {
  Vector values;   // ascending
  Matrix vectors;  // columns: unit (Euclidean) eigenvectors, sign fixed: largest entry positive
};

// Sorts the pairs ascending and makes each vector unit with its sign fixed (largest entry
// positive), so that results are reproducible whatever a solver's internal sign.
void normalise_eigenpairs(Vector values, Matrix vectors, Eigenpairs& out);

// K symmetric, both triangles stored; `factorization` of K at its shift() (usually 0); `make`
// builds the factorizations at lower shifts (empty: SparseLdlt). k is clipped to K's size. false
// if Spectra did not converge or no usable shift was found.
bool lowest_eigenpairs(const SparseMatrix& K, int k, const SymmetricFactorization& factorization,
                       const EigenOptions& options, Eigenpairs& out,
                       const FactorizationFactory& make = {});

}  // namespace si::cont
