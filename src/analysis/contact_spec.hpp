// How the indenter and the shell interact (docs/case-file.md `contact`): which face is pressed,
// the solver, the local (through-thickness) law and the traction (indentation_run.hpp turns it
// into the problem's options).
#pragma once

#include "contact/local_support.hpp"

namespace si {

enum class ContactSurface { kOuter, kMid };
enum class ContactSolver { kKinsol, kActiveSet };
enum class LocalContactModel { kNone, kHertz, kYangSun, kVam, kAnisotropic };

// Contact traction: nodal Lagrange multipliers (forces), or the paper's interpolated traction
// with weighted gaps (indentation/weighted_gaps.hpp; linear kinematics only).
enum class ContactTraction { kNodal, kInterpolated };

struct ContactSpec {
  ContactSurface surface = ContactSurface::kOuter;  // outer = top face of the laminate
  ContactSolver solver = ContactSolver::kKinsol;
  LocalContactModel local = LocalContactModel::kNone;
  // local: anisotropic only (contact/local_support.hpp).
  LocalSupport local_support = LocalSupport::kHalfSpace;
  LocalPlies local_plies = LocalPlies::kHomogenised;
  ContactTraction traction = ContactTraction::kNodal;
  bool fbar = false;  // the paper's F-bar coupling term; needs traction: interpolated
};

}  // namespace si
