// An element's generalised strains at its four nodes as linear maps of its linear-mode dofs,
// R_a = B_a q (shell_element.hpp: in linear mode ShellElement::strains_at_nodes is B q exactly),
// for the terms that need the strains' gradient: the F-bar rows of the interpolated traction
// (indentation/interpolated_contact.cpp) and of the nodal contact
// (indentation/face_thickening.hpp).
#pragma once

#include <array>

#include "shell/shell_element.hpp"

namespace si {

using StrainMatrix = Eigen::Matrix<double, 6, kShellElementDofs>;

// Column by column from the unit dofs. A rotation dof is set by one rotate_node call, which the
// element inverts exactly.
std::array<StrainMatrix, 4> nodal_strain_matrices(const ShellElement& element,
                                                  const ElementGeometry& geometry);

}  // namespace si
