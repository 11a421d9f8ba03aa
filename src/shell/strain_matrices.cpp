#include "shell/strain_matrices.hpp"

#include "shell/director.hpp"

namespace si {

std::array<StrainMatrix, 4> nodal_strain_matrices(const ShellElement& element,
                                                  const ElementGeometry& geometry) {
  std::array<NodeState, 4> reference;
  for (int a = 0; a < 4; ++a) reference[a] = reference_node_state(geometry.D[a]);
  std::array<StrainMatrix, 4> B;
  for (int k = 0; k < kShellElementDofs; ++k) {
    std::array<NodeState, 4> nodes = reference;
    const int a = k / kShellNodeDofs, l = k % kShellNodeDofs;
    if (l < 3)
      nodes[a].u[l] = 1.0;
    else
      rotate_node(nodes[a], l == 3 ? 1.0 : 0.0, l == 4 ? 1.0 : 0.0);
    const ElementStrains s = element.strains_at_nodes(geometry, nodes, Kinematics::kLinear);
    for (int b = 0; b < 4; ++b) B[b].col(k) = s.R[b];
  }
  return B;
}

}  // namespace si
