// The discretisation error a converged point carries, estimated a posteriori by Zienkiewicz-Zhu
// recovery on the shell's generalised strains (Zienkiewicz & Zhu, IJNME 24 (1987) 337; design in
// docs/theory/discretisation-error.md):
//  * e_h: each element's strains R, gamma (shell_law.hpp order), bilinear from its 2x2 Gauss
//    points (ShellElement::strains_at_nodes);
//  * e*: the recovered, continuous field, the nodal average of the elements' nodal values
//    (nodal_resultants.hpp), interpolated bilinearly;
//  * |e|^2 = sum over elements and their 2x2 Gauss points of J w (e* - e_h)' D (e* - e_h), D the
//    section law (A_R on R, G on gamma): the estimated energy norm of the error, and
//    |u|^2 = the same sum of e_h' D e_h (twice the strain energy with linear kinematics).
// The relative error sqrt(|e|^2 / (|u|^2 + |e|^2)) is ZZ's normalisation. It is an energy norm
// over the whole mesh: a point load's singular term near the apex is what it sees first.
#pragma once

#include <vector>

#include "model/assembler.hpp"
#include "model/mesh.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si {

struct RecoveryError {
  double error_norm2 = 0;     // |e|^2, N mm
  double solution_norm2 = 0;  // |u|^2, N mm
  // sqrt(|e|^2 / (|u|^2 + |e|^2)); 0 for a zero field.
  double relative() const;
};

RecoveryError recovery_error(const Mesh& mesh, const Assembler& assembler,
                             const ShellElement& element, const ShellLaw& law,
                             const std::vector<NodeState>& state);

}  // namespace si
