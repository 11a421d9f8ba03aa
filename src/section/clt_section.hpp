// Classical lamination theory (CLT) stiffness of a laminate (Jones 1999, chapter 4; Reddy 2004,
// section 3.3; vam.md section 10.1).
//
// Ordering: Yu's R = [e11, 2e12, e22, k11, k12+k21, k22] with resultants [N11, N12, N22, M11,
// M12, M22]; units N/mm (A), N (B), N*mm (D). The conventional textbook / SwiftComp order
// [e11, e22, 2e12, k11, k22, 2k12] is the permutation {0, 2, 1, 3, 5, 4} of it (vam.md
// section 13): mixing the two silently swaps A12 and A16. See docs/theory/clt-fsdt.md.
#pragma once

#include "core/linalg.hpp"
#include "section/laminate.hpp"

namespace si {

// ABD = sum_k [[Q_k t_k, Q_k t_k zbar_k], [Q_k t_k zbar_k, Q_k (t_k zbar_k^2 + t_k^3/12)]]
// about the mid-surface (zbar_k = ply centre), then moved to laminate.reference_offset with
// shift_reference. Q_k is reduced_stiffness(ply k). Validates the laminate (input si::Error).
Matrix6d clt_abd(const Laminate& laminate);

// The 3x3 blocks of a 6x6 plate stiffness [[A, B], [B^T, D]].
inline Matrix3d a_block(const Matrix6d& abd) {
  return abd.topLeftCorner<3, 3>();
}
inline Matrix3d b_block(const Matrix6d& abd) {
  return abd.topRightCorner<3, 3>();
}
inline Matrix3d d_block(const Matrix6d& abd) {
  return abd.bottomRightCorner<3, 3>();
}

// Reorders a 6x6 plate stiffness between Yu order and the conventional order
// [e11, e22, 2e12, k11, k22, 2k12]. The permutation is its own inverse, so this converts both
// ways.
Matrix6d swap_yu_conventional_order(const Matrix6d& abd);

// Specially orthotropic in model axes (Jones 1999, section 4.3): A16 = A26 = D16 = D26 = 0 and
// B = 0, each within rel_tol of its block's largest entry (B against sqrt(max|A| max|D|)).
// Such a plate has the symmetries that allow quarter models. Throws an input si::Error if
// rel_tol is negative or not finite.
bool is_specially_orthotropic(const Matrix6d& abd, double rel_tol);

// True if the stack mirrors about the mid-surface: ply k and ply N-1-k have equal thickness
// (relative 1e-12) and equal stiffness in plate axes (relative 1e-12, so angles may differ by
// 180 deg). Independent of the reference surface. Such a stack has B = 0 about the mid-surface.
bool is_symmetric_layup(const Laminate& laminate);

}  // namespace si
