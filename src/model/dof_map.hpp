// Degrees of freedom of a shell model: 5 per node (shell/shell_element.hpp: u1 u2 u3 along the
// global axes, then rotation increments about the node's current v1 and v2), numbered node-major:
// global dof = 5 * node + local. Some dofs are prescribed (with a value: zero for supports, any
// value for prescribed translations); the others are free and get consecutive equation numbers
// in global-dof order, which are the rows/columns of the assembled tangent.
#pragma once

#include <array>
#include <vector>

#include "shell/shell_element.hpp"

namespace si {

struct PrescribedDof {
  int dof = 0;       // global dof
  double value = 0;  // mm for translations, rad for rotations (only 0 is meaningful for those)
};

using ElementDofs = std::array<int, 4 * kShellNodeDofs>;

class DofMap {
 public:
  // Throws an input error for a dof outside [0, 5 num_nodes) or a dof prescribed twice with
  // different values (the same value twice is accepted: node sets of two supports may overlap).
  DofMap(int num_nodes, const std::vector<PrescribedDof>& prescribed);

  static int dof(int node, int local) { return kShellNodeDofs * node + local; }
  static ElementDofs element_dofs(const std::array<int, 4>& nodes);

  int num_nodes() const { return num_nodes_; }
  int num_dofs() const { return kShellNodeDofs * num_nodes_; }
  int num_free() const { return num_free_; }
  int num_prescribed() const { return num_dofs() - num_free_; }

  // Equation number of a global dof, -1 if the dof is prescribed.
  int equation(int dof) const { return equation_[dof]; }
  bool is_prescribed(int dof) const { return equation_[dof] < 0; }
  double prescribed_value(int dof) const { return value_[dof]; }
  // Prescribed dofs in increasing order.
  const std::vector<int>& prescribed_dofs() const { return prescribed_; }
  // Global dof of each equation.
  const std::vector<int>& free_dofs() const { return free_; }

  // Full (all-dof) vector <-> free-dof vector.
  Eigen::VectorXd restrict_to_free(const Eigen::VectorXd& full) const;
  // Full vector with `free` at the free dofs and prescribed_value * scale at the prescribed ones.
  Eigen::VectorXd expand(const Eigen::VectorXd& free, double scale) const;

  // Element dof vectors from/into a full vector (20 entries, node-major).
  static Eigen::Matrix<double, 20, 1> gather(const ElementDofs& dofs, const Eigen::VectorXd& full);
  static void scatter_add(const ElementDofs& dofs, const Eigen::Matrix<double, 20, 1>& local,
                          Eigen::VectorXd& full);

 private:
  int num_nodes_;
  int num_free_ = 0;
  std::vector<int> equation_;
  std::vector<double> value_;
  std::vector<int> prescribed_;
  std::vector<int> free_;
};

}  // namespace si
