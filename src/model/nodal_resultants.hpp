// Stress resultants at the nodes, for output (paper P14: strains at nodes recovered from the
// Gauss points by extrapolation).
//
// Each element extrapolates its generalised strains R bilinearly from its 2x2 Gauss points to its
// four nodes (ShellElement::strains_at_nodes); the resultants follow from the
// averaged strains as A_R R and G gamma (shell_law.hpp), in the element's local frame (t1 = global
// x projected on the surface). A node's value is the unweighted arithmetic mean over the elements
// that share it. On a smooth surface the frames of neighbouring elements at a node differ only by
// the angle between their normals, so the mean is meaningful there; at a kink of the surface it is
// not.
#pragma once

#include <vector>

#include "core/linalg.hpp"
#include "model/assembler.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si {

// One row per node, averaged over elements: the generalised strains
// e11, 2e12, e22, k11, k12+k21, k22 (1/mm for curvatures), 2g13, 2g23.
Eigen::MatrixXd nodal_strains(const Mesh& mesh, const Assembler& assembler,
                              const ShellElement& element, const std::vector<NodeState>& state);

// The two steps of nodal_strains, for a caller that also needs each element's own values (the
// recovery error estimate, recovery_error.hpp): every element's strains at its nodes, and their
// average at the nodes (one row per node, the order above).
std::vector<ElementStrains> element_strains(const Mesh& mesh, const Assembler& assembler,
                                            const ShellElement& element,
                                            const std::vector<NodeState>& state);
Eigen::MatrixXd average_at_nodes(const Mesh& mesh, const std::vector<ElementStrains>& strains);

// The same average at one node over `elements`, the elements that contain it (cheaper when only
// a few nodes are wanted, e.g. the apex curvature along a path).
Eigen::Matrix<double, 1, 8> nodal_strain_at(const Mesh& mesh, const Assembler& assembler,
                                            const ShellElement& element,
                                            const std::vector<NodeState>& state, int node,
                                            const std::vector<int>& elements);

// The resultants of nodal strains (one row per node, as above): N11, N12, N22 (N/mm),
// M11, M12, M22 (N mm/mm), Q1, Q2 (N/mm), i.e. [A_R R; G gamma].
Eigen::MatrixXd nodal_resultants(const Eigen::MatrixXd& strains, const ShellLaw& law);

}  // namespace si
