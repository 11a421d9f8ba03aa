// The local contact law `anisotropic` of a laminate (docs/theory/local-indentation.md section 6):
// a sphere of relative radius R on the laminate's outer face, the face carried by
//  * kHalfSpace: a homogeneous anisotropic half-space of the upper half's homogenised stiffness
//    (or the top ply's, kResolved): F = (4/3) E_W R^0.5 alpha^1.5 with Willis' modulus
//    (anisotropic_half_space.hpp) and Hertz's dent;
//  * kBondedBase, kFrictionlessBase: the upper half (mid-surface to outer face; homogenised into
//    one layer or ply by ply) on a rigid base at the mid-surface;
//  * kPlate: the whole laminate as a free plate, the face's approach to the mid-plane without the
//    Poisson thickness change of plate bending (the shell's transverse shear stiffness from the
//    VAM section, section/vam_section.hpp, sets where that term fades);
// the last three tabulated over the contact radius (layer_contact_law.hpp);
//  * kShell: the whole laminate's face against the shell's own plate, non-local
//    (face_influence.hpp), its plies always resolved: the kernel is the difference of two plates
//    of the same laminate, and a homogenised one would not be the shell's.
// The indenter's own half-space compliance 2 (1 - nu_i^2) / E_i (0: rigid) adds to the face's.
#pragma once

#include "contact/local_contact_law.hpp"
#include "contact/local_support.hpp"
#include "section/laminate.hpp"

namespace si {

struct AnisotropicLawSpec {
  LocalSupport support = LocalSupport::kHalfSpace;
  LocalPlies plies = LocalPlies::kHomogenised;
  double sphere_radius = 0;        // R, mm (relative radius on a cap)
  double indenter_compliance = 0;  // 2 (1 - nu_i^2) / E_i, 1/MPa
};

// Throws an input si::Error for a non-positive radius or negative indenter compliance.
LocalContactLaw anisotropic_local_law(const Laminate& laminate, const AnisotropicLawSpec& spec);

}  // namespace si
