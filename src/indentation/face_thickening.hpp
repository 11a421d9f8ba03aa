// The F-bar face term on the nodal contact rows (contact.fbar with contact.traction: nodal; the
// paper's eqs 13, 18, 75 and vam.md 7.4, U3(h/2) = u3 - R^T Fbar+): the laminate's Poisson
// thickness change under the shell's strains R moves the loaded face by -R^T Fbar+ along the
// director. At a contact node R is its elements' strains there, averaged with the weights of the
// interpolated traction's nodal (lumped) rule, each element's contact-face area element at the
// node, so node i's gap gains (a_i . n_i)(-R_i^T Fbar+), a_i its gap's gradient on the face point
// and n_i its director: the interpolated traction's term (interpolated_contact.hpp) with that
// rule, to round-off. Why on the nodal rows: a finite-thickness local law removes this thickening
// from its own approach (docs/theory/local-indentation.md 6.4) for the shell to carry, and without
// it the upper half's thickening under the shell's bending (1.5-1.8 % of the travel on the paper's
// cap, 6.7) is lost. Linear kinematics: R = B q, so the face's rise is a fixed row of the free
// dofs.
#pragma once

#include <utility>
#include <vector>

#include "core/linalg.hpp"
#include "indentation/shell_part.hpp"

namespace si {

// A linear form on the free dofs: (equation, coefficient) pairs.
using DofRow = std::vector<std::pair<int, double>>;

class FaceThickening {
 public:
  // fbar_top: the section's Fbar+ (VamSection::Fbar_top) in the elements' frames; offset: the
  // contact face above the reference surface along the director, mm. Linear kinematics only (an
  // si::Error otherwise). Keeps a reference to the shell.
  FaceThickening(const ShellPart& shell, const Vector6d& fbar_top, double offset);

  // The rise -R^T Fbar+ (mm) of mesh node `node`'s face along its director as a row of the free
  // dofs (mm per mm or rad).
  DofRow rise_row(int node) const;
  // Its director (the reference one: linear kinematics).
  const Vector3d& director(int node) const;

 private:
  const ShellPart& shell_;
  Vector6d fbar_top_;
  double offset_;
};

// row . x
double row_dot(const DofRow& row, const Eigen::Ref<const Eigen::VectorXd>& x);

}  // namespace si
