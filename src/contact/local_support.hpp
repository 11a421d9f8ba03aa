// The choices of the anisotropic local contact law (`contact.local: anisotropic`,
// docs/case-file.md; docs/theory/local-indentation.md section 6): what carries the face under the
// indenter, and how the plies enter it.
#pragma once

namespace si {

enum class LocalSupport {
  kHalfSpace,         // the laminate as a homogeneous anisotropic half-space (Willis 1966)
  kBondedBase,        // its upper half bonded to a rigid base at the mid-surface
  kFrictionlessBase,  // its upper half on a frictionless rigid base at the mid-surface
  kPlate,             // the whole laminate as a free plate, top face against the mid-plane
  kShell,             // the whole laminate's face against the shell's own plate, non-local
                      // (contact/face_influence.hpp)
};

enum class LocalPlies {
  kHomogenised,  // one layer of the plies' homogenised stiffness
                 // (section/homogenised_stiffness.hpp)
  kResolved,     // each ply as it is (half_space: the top ply alone)
};

}  // namespace si
