// Stress resultants at the nodes, for output (paper P14: strains at nodes recovered from the
// Gauss points by extrapolation).
//
// Each element extrapolates its generalised strains R bilinearly from its 2x2 Gauss points to its
// four nodes (ShellElement::strains_at_nodes); the resultants of that element at the node are
// A_R R (shell_law.hpp), in the element's local frame (t1 = global x projected on the surface).
// A node's value is the unweighted arithmetic mean over the elements that share it. On a smooth
// surface the frames of neighbouring elements at a node differ only by the angle between their
// normals, so the mean is meaningful there; at a kink of the surface it is not.
#pragma once

#include <vector>

#include "core/linalg.hpp"
#include "model/assembler.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si {

// One row per node: N11, N12, N22 (N/mm), M11, M12, M22 (N mm/mm), averaged over elements.
Eigen::MatrixXd nodal_resultants(const Mesh& mesh, const Assembler& assembler,
                                 const ShellElement& element, const ShellLaw& law,
                                 const std::vector<NodeState>& state);

}  // namespace si
