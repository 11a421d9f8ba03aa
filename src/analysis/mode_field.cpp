#include "analysis/mode_field.hpp"

namespace si {

Eigen::MatrixXd mode_translations(const DofMap& dofs, const Eigen::VectorXd& mode, int nodes) {
  Eigen::MatrixXd u = Eigen::MatrixXd::Zero(nodes, 3);
  for (int n = 0; n < nodes; ++n)
    for (int l = 0; l < 3; ++l) {
      const int eq = dofs.equation(DofMap::dof(n, l));
      if (eq >= 0 && eq < mode.size()) u(n, l) = mode[eq];
    }
  const double largest = u.cwiseAbs().maxCoeff();
  return largest > 0 ? Eigen::MatrixXd(u / largest) : u;
}

}  // namespace si
