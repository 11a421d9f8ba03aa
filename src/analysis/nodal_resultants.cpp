#include "analysis/nodal_resultants.hpp"

namespace si {

Eigen::MatrixXd nodal_resultants(const Mesh& mesh, const Assembler& assembler,
                                 const ShellElement& element, const ShellLaw& law,
                                 const std::vector<NodeState>& state) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(mesh.num_nodes(), 6);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(mesh.num_nodes());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const ElementStrains s = element.strains_at_nodes(
        assembler.geometry(e), assembler.element_states(state, e), assembler.kinematics());
    for (int a = 0; a < 4; ++a) {
      const int n = mesh.elements[e][a];
      sum.row(n) += (law.A_R * s.R[a]).transpose();
      count[n] += 1;
    }
  }
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (count[n] > 0) sum.row(n) /= count[n];
  return sum;
}

}  // namespace si
