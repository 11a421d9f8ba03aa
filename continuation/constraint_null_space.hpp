// An orthonormal basis Z of the null space of sparse constraint rows A (m x n), built from local
// Householder reflections, for the tangent restricted to the constraints, Z' K Z
// (docs/theory/continuation.md, "Stability on constraints").
//
// Rows whose supports (their nonzero columns) overlap are grouped (connected components of the
// overlap graph); for the contact problem each active constraint touches one node's dofs and the
// groups are single rows. For a group with rows B (m_g x d_g on its d_g columns), a Householder QR
// with column pivoting B' P = Q R (Q = H_1 ... H_r, d_g x d_g orthogonal) gives the rank r of B
// (pivots |R_ii| > rank_tolerance * |R_11|) and null(B) = span of Q's last d_g - r columns. Z
// takes those columns at the group's dofs and the unit vector e_j for every dof no row touches:
// Z is n x (n - rank A), block diagonal up to a column permutation, Z' Z = I and A Z = 0 to
// rounding. Columns follow the dofs' order (a group's at its first dof), so Z' K Z keeps the
// node-block sparsity of K.
#pragma once

#include "continuation/sparse_matrix.hpp"

namespace si::cont {

struct NullSpaceBasis {
  SparseMatrix Z;  // n x (n - rank)
  int rank = 0;    // rank of A
};

// Throws std::invalid_argument if a row has a non-finite entry.
NullSpaceBasis constraint_null_space(const SparseMatrix& A, double rank_tolerance = 1e-12);

// Z' K Z for K symmetric (both triangles stored), symmetrised exactly.
SparseMatrix restrict_to_null_space(const SparseMatrix& K, const SparseMatrix& Z);

}  // namespace si::cont
