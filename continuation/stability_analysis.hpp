// Stability of a symmetric tangent K restricted to linear constraints A v = 0: the number of
// negative eigenvalues of Z' K Z (Z an orthonormal basis of null(A), constraint_null_space.hpp) by
// the inertia of its LDL' (inertia.hpp), and its lowest eigenpairs by shift-invert Lanczos on the
// same factorization (lowest_eigenpairs.hpp), the modes mapped back to K's space as Z w. With
// Z' Z = I these are the extrema of the Rayleigh quotient v'Kv / v'v over null(A)
// (Courant-Fischer), i.e. the second-order stability condition of the constrained equilibrium when
// K is the Hessian of the Lagrangian (e.g. Nocedal & Wright 2006, Thm 12.5). Theory:
// docs/theory/continuation.md.
#pragma once

#include "continuation/lowest_eigenpairs.hpp"
#include "continuation/stability.hpp"

namespace si::cont {

struct StabilityOptions {
  EigenOptions eigen;
  // The factorization of the restricted tangent (inertia.hpp); empty: SparseLdlt with
  // zero_pivot_tolerance. For large problems cholmod_first_factorization()
  // (cholmod_factorization.hpp) is several times faster.
  FactorizationFactory factorization;
  double zero_pivot_tolerance = 1e-12;  // SparseLdlt, inertia.hpp
  double rank_tolerance = 1e-12;        // constraint_null_space.hpp
};

// K: n x n symmetric (both triangles); A: m x n constraint rows (m may be 0). Fills `out` with the
// counts and the lowest `modes` eigenpairs, the modes of length n (K's space). false when the
// restricted tangent cannot be factored or Lanczos does not converge.
bool analyse_stability(const SparseMatrix& K, const SparseMatrix& A, int modes, Stability& out,
                       const StabilityOptions& options = {});

// psi = -(A A')^-1 A K v: the multipliers' part of a null vector [v; psi] of the bordered
// [K A'; A 0] when v = Z w with Z' K Z w = 0 (K v then lies in range(A'), and this is its exact
// coefficient); the least-squares multiplier change elsewhere. A full row rank.
Vector multiplier_direction(const SparseMatrix& K, const SparseMatrix& A, const Vector& v);
// The same from the product K v.
Vector multiplier_direction_from_product(const SparseMatrix& A, const Vector& Kv);

}  // namespace si::cont
