// Rotation of a ply's 3-D stiffness from material axes to laminate (plate) axes, and the
// reordering to the Yu ordering used by the section analysis (vam.md section 1).
//
// Angle convention: the fibre direction is rotated by +theta from x1 towards x2, i.e. a
// right-handed rotation about +x3 (the laminate normal, pointing from the first listed ply to
// the last). Checked against SwiftComp: A16 > 0 for a +45 deg ply (vam.md section 11.2).
#pragma once

#include "core/linalg.hpp"

namespace si {

// C_std = T C' T^T in Voigt order [11, 22, 33, 23, 13, 12] (engineering shear strains).
Matrix6d rotate_stiffness_voigt(const Matrix6d& C_material, double angle_deg);

// Permutes Voigt [11, 22, 33, 23, 13, 12] to Yu order [11, 12, 22, 13, 23, 33].
Matrix6d voigt_to_yu(const Matrix6d& C_voigt);

// rotate_stiffness_voigt followed by voigt_to_yu: the ply stiffness the section analysis uses.
Matrix6d ply_stiffness_yu(const Matrix6d& C_material, double angle_deg);

}  // namespace si
