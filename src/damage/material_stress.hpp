// The 3-D stress of a ply in its material axes (1 = fibre, 2 = in-plane transverse, 3 = normal),
// the input of every failure criterion in this directory. Units MPa.
#pragma once

#include "core/linalg.hpp"

namespace si {

struct MaterialStress {
  double s11 = 0, s22 = 0, s33 = 0;  // normal stresses
  double s12 = 0, s13 = 0, s23 = 0;  // shear stresses
};

// Rotates a stress in plate axes, Yu order [11, 12, 22, 13, 23, 33] (the order of the 3-D
// recovery, section/through_thickness_recovery.hpp), into the material axes of a ply whose fibre
// lies at angle_deg from x1 towards x2 about +x3 (material/ply_rotation.hpp):
//   s11 = c^2 sxx + s^2 syy + 2cs txy,  s22 = s^2 sxx + c^2 syy - 2cs txy,
//   s12 = cs (syy - sxx) + (c^2 - s^2) txy,  s13 = c txz + s tyz,  s23 = c tyz - s txz.
MaterialStress to_material_axes(const Vector6d& stress_yu, double angle_deg);

// The stress scaled by a factor (proportional loading).
MaterialStress scaled(const MaterialStress& s, double factor);

}  // namespace si
