// The contraction (a b)_jk = a_i C_ijkl b_l of a 3-D elastic stiffness with two vectors, the
// building block of the Stroh and Barnett-Lothe formalisms of anisotropic elasticity (Ting,
// Anisotropic Elasticity, 1996, eq. 5.2-3: Q = (n n), R = (n m), T = (m m)): (a a) is the
// acoustic (Christoffel) tensor of the direction a, and the traction on a plane of normal a due to
// a displacement gradient u_k,l = v_k b_l is (a b) v. C is given in Voigt order
// [11, 22, 33, 23, 13, 12] (engineering shear strains, material/material.hpp), MPa; the result
// has the units of C.
#pragma once

#include "core/linalg.hpp"

namespace si {

Matrix3d stiffness_contraction(const Matrix6d& C_voigt, const Vector3d& a, const Vector3d& b);

}  // namespace si
