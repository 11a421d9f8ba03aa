#include "model/dof_map.hpp"

#include <cmath>

#include "core/error.hpp"

namespace si {
namespace {

std::string describe_dof(int dof) {
  static const char* const kNames[kShellNodeDofs] = {"u1", "u2", "u3", "rotation v1",
                                                     "rotation v2"};
  return "node " + std::to_string(dof / kShellNodeDofs) + " dof " + std::to_string(dof) + " (" +
         kNames[dof % kShellNodeDofs] + ")";
}

}  // namespace

DofMap::DofMap(int num_nodes, const std::vector<PrescribedDof>& prescribed)
    : num_nodes_(num_nodes) {
  SI_REQUIRE(num_nodes >= 0, "a dof map needs a non-negative number of nodes");
  const int n = num_dofs();
  equation_.assign(n, 0);
  value_.assign(n, 0.0);
  for (const PrescribedDof& p : prescribed) {
    if (p.dof < 0 || p.dof >= n)
      throw_input("prescribed dof " + std::to_string(p.dof) + " is outside the model's " +
                  std::to_string(n) + " dofs");
    if (!std::isfinite(p.value))
      throw_input("prescribed value of " + describe_dof(p.dof) + " is not finite");
    if (equation_[p.dof] < 0 && value_[p.dof] != p.value)
      throw_input(describe_dof(p.dof) + " is prescribed twice with different values (" +
                  std::to_string(value_[p.dof]) + " and " + std::to_string(p.value) + ")");
    equation_[p.dof] = -1;
    value_[p.dof] = p.value;
  }
  for (int dof = 0; dof < n; ++dof) {
    if (equation_[dof] < 0) {
      prescribed_.push_back(dof);
    } else {
      equation_[dof] = num_free_++;
      free_.push_back(dof);
    }
  }
}

ElementDofs DofMap::element_dofs(const std::array<int, 4>& nodes) {
  ElementDofs dofs;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < kShellNodeDofs; ++i) dofs[kShellNodeDofs * a + i] = dof(nodes[a], i);
  return dofs;
}

Eigen::VectorXd DofMap::restrict_to_free(const Eigen::VectorXd& full) const {
  SI_ASSERT(full.size() == num_dofs());
  Eigen::VectorXd free(num_free_);
  for (int e = 0; e < num_free_; ++e) free[e] = full[free_[e]];
  return free;
}

Eigen::VectorXd DofMap::expand(const Eigen::VectorXd& free, double scale) const {
  SI_ASSERT(free.size() == num_free_);
  Eigen::VectorXd full(num_dofs());
  for (int e = 0; e < num_free_; ++e) full[free_[e]] = free[e];
  for (int dof : prescribed_) full[dof] = scale * value_[dof];
  return full;
}

Eigen::Matrix<double, 20, 1> DofMap::gather(const ElementDofs& dofs, const Eigen::VectorXd& full) {
  Eigen::Matrix<double, 20, 1> local;
  for (int i = 0; i < 20; ++i) local[i] = full[dofs[i]];
  return local;
}

void DofMap::scatter_add(const ElementDofs& dofs, const Eigen::Matrix<double, 20, 1>& local,
                         Eigen::VectorXd& full) {
  for (int i = 0; i < 20; ++i) full[dofs[i]] += local[i];
}

}  // namespace si
