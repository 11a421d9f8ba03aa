#include "model/nodal_resultants.hpp"

namespace si {

std::vector<ElementStrains> element_strains(const Mesh& mesh, const Assembler& assembler,
                                            const ShellElement& element,
                                            const std::vector<NodeState>& state) {
  std::vector<ElementStrains> out(static_cast<std::size_t>(mesh.num_elements()));
  for (int e = 0; e < mesh.num_elements(); ++e)
    out[e] = element.strains_at_nodes(assembler.geometry(e), assembler.element_states(state, e),
                                      assembler.kinematics());
  return out;
}

Eigen::MatrixXd average_at_nodes(const Mesh& mesh, const std::vector<ElementStrains>& strains) {
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(mesh.num_nodes(), 8);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(mesh.num_nodes());
  for (int e = 0; e < mesh.num_elements(); ++e)
    for (int a = 0; a < 4; ++a) {
      const int n = mesh.elements[e][a];
      sum.row(n).head<6>() += strains[e].R[a].transpose();
      sum.row(n).tail<2>() += strains[e].gamma[a].transpose();
      count[n] += 1;
    }
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (count[n] > 0) sum.row(n) /= count[n];
  return sum;
}

Eigen::MatrixXd nodal_strains(const Mesh& mesh, const Assembler& assembler,
                              const ShellElement& element, const std::vector<NodeState>& state) {
  return average_at_nodes(mesh, element_strains(mesh, assembler, element, state));
}

Eigen::Matrix<double, 1, 8> nodal_strain_at(const Mesh& mesh, const Assembler& assembler,
                                            const ShellElement& element,
                                            const std::vector<NodeState>& state, int node,
                                            const std::vector<int>& elements) {
  Eigen::Matrix<double, 1, 8> sum = Eigen::Matrix<double, 1, 8>::Zero();
  int count = 0;
  for (int e : elements) {
    const ElementStrains s = element.strains_at_nodes(
        assembler.geometry(e), assembler.element_states(state, e), assembler.kinematics());
    for (int a = 0; a < 4; ++a)
      if (mesh.elements[e][a] == node) {
        sum.head<6>() += s.R[a].transpose();
        sum.tail<2>() += s.gamma[a].transpose();
        ++count;
      }
  }
  return count > 0 ? Eigen::Matrix<double, 1, 8>(sum / count) : sum;
}

Eigen::MatrixXd nodal_resultants(const Eigen::MatrixXd& strains, const ShellLaw& law) {
  Eigen::MatrixXd out(strains.rows(), 8);
  out.leftCols<6>() = strains.leftCols<6>() * law.A_R.transpose();
  out.rightCols<2>() = strains.rightCols<2>() * law.G.transpose();
  return out;
}

}  // namespace si
