// Plane-stress reduced stiffness of a ply in plate axes, the in-plane law of classical
// lamination theory (vam.md section 5.2).
//
// Component order is Yu's [11, 12, 22] with engineering shear strain 2e12, i.e.
//   Q = [[Q11b, Q16b, Q12b], [Q16b, Q66b, Q26b], [Q12b, Q26b, Q22b]]   (MPa)
// in the textbook symbols of Jones (1999, section 2.6) and Reddy (2004, section 2.3).
#pragma once

#include "core/linalg.hpp"
#include "section/laminate.hpp"

namespace si {

// Q = (in-plane 3x3 block of C^-1)^-1 for a 3-D stiffness C in Yu order [11, 12, 22, 13, 23,
// 33]: the Schur complement that imposes s13 = s23 = s33 = 0. For monoclinic plies (any
// rotation about x3) it equals the textbook rotated Q-bar (vam.md section 10.1); it is computed
// from the 3-D law so that CLT and the VAM zeroth-order stiffness share one definition.
// Throws a numerical si::Error if C is not positive definite.
Matrix3d reduced_stiffness_yu(const Matrix6d& C_yu);

// reduced_stiffness_yu of the ply's stiffness in plate axes.
Matrix3d reduced_stiffness(const Ply& ply);

}  // namespace si
