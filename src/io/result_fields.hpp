// The nodal fields every VTU output of shellindent carries (static and indentation runs):
// generalised strains and resultants at the nodes, averaged over elements
// (nodal_resultants.hpp), under the names ParaView users see.
#pragma once

#include <vector>

#include "io/vtu_writer.hpp"
#include "model/assembler.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si {

// membrane_strain (e11, 2e12, e22), curvature (k11, k12+k21, k22, 1/mm), shear_strain_13/23,
// N (N/mm), M (N mm/mm), Q1, Q2 (N/mm).
VtuFields resultant_fields(const Mesh& mesh, const Assembler& assembler,
                           const ShellElement& element, const ShellLaw& law,
                           const std::vector<NodeState>& state);

}  // namespace si
