// Stability of a symmetric K restricted to null(A) from a factorization of the penalised matrix
// P = K + rho A'A that a solver already has (e.g. the Krylov preconditioner of a contact problem,
// which condenses the active constraints as a penalty), instead of forming and factoring Z'KZ
// (stability_analysis.hpp).
//
// In an orthonormal basis [Z Y] with Z spanning null(A) and Y range(A'), P = [Kzz Kzy; Kyz Kyy +
// rho B] with B = Y'A'AY positive definite, and the Z block of P^-1 is the inverse of the Schur
// complement S = Kzz - Kzy (Kyy + rho B)^-1 Kyz (Golub & Van Loan 2013, 3.2.11). Hence:
// - the count is exact: P positive definite implies Z'KZ = Kzz positive definite (on null(A),
//   v'Kv = v'Pv > 0). When P is not positive definite the caller analyses Z'KZ itself
//   (analyse_stability): P's inertia says nothing exact about Kzz then;
// - the eigenvalues are those of S, the exact ones lowered by at most ||Kzy||^2 / (rho
// lambda_min(B))
//   (S <= Kzz; Weyl), a relative O(||K|| / rho) error on the stiffness scale: conservative;
// - S^-1 = Z'P^-1 Z, so the largest eigenvalues theta of Pi P^-1 Pi (Pi = I - A'(AA')^-1 A the
//   orthogonal projector on null(A)) are 1/lambda for the lowest eigenvalues lambda of S, found by
//   Lanczos (Spectra's SymEigsSolver) with one solve with P per product, like shift-invert at 0.
// Theory: docs/theory/continuation.md, "Stability".
#pragma once

#include <functional>

#include "continuation/lowest_eigenpairs.hpp"
#include "continuation/stability.hpp"

namespace si::cont {

// out = P^-1 in, with P = K + rho A'A positive definite.
using PenalizedSolve = std::function<void(const Vector& in, Vector& out)>;

// A: m x n constraint rows of full row rank (m may be 0); n: K's size. Fills `out` (negative =
// zero = 0, the lowest `modes` eigenpairs of S, the modes unit vectors in null(A)) and returns
// true; false if Lanczos did not converge or the restricted space is too small for it (at most
// options.dense_size + 1 dimensions: analyse that with analyse_stability).
bool stability_from_penalized(const PenalizedSolve& solve, const SparseMatrix& A, Eigen::Index n,
                              int modes, const EigenOptions& options, Stability& out);

}  // namespace si::cont
