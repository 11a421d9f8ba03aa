// Test-only helpers for the shell element tests: a tiny dense assembler and Dirichlet solve
// (the production sparse assembler lives in src/model/), meshes as raw arrays.
#pragma once

#include <array>
#include <map>
#include <vector>

#include <Eigen/Dense>

#include "shell/shell_element.hpp"

namespace si::test {

struct ShellMesh {
  std::vector<Vector3d> X;
  std::vector<Vector3d> D;
  std::vector<std::array<int, 4>> quads;
  Vector3d material_axis{1, 0, 0};

  int dofs() const { return kShellNodeDofs * static_cast<int>(X.size()); }
  ElementGeometry geometry(int e) const {
    ElementGeometry g;
    for (int i = 0; i < 4; ++i) {
      g.X[i] = X[quads[e][i]];
      g.D[i] = D[quads[e][i]];
    }
    g.material_axis = material_axis;
    return g;
  }
};

// Node states of a linear solution q (u, rotations about the reference axes).
inline std::vector<NodeState> states_from_dofs(const ShellMesh& mesh, const Eigen::VectorXd& q) {
  std::vector<NodeState> s;
  for (size_t n = 0; n < mesh.X.size(); ++n) {
    NodeState node = reference_node_state(mesh.D[n]);
    const int k = kShellNodeDofs * static_cast<int>(n);
    node.u = q.segment<3>(k);
    rotate_node(node, q(k + 3), q(k + 4));
    s.push_back(node);
  }
  return s;
}

inline std::array<NodeState, 4> element_states(const ShellMesh& mesh,
                                               const std::vector<NodeState>& states, int e) {
  std::array<NodeState, 4> s;
  for (int i = 0; i < 4; ++i) s[i] = states[mesh.quads[e][i]];
  return s;
}

// Dense linear-mode stiffness at the reference state.
inline Eigen::MatrixXd assemble_linear_stiffness(const ShellElement& element, const ShellMesh& mesh,
                                                 const ShellLaw& law) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(mesh.dofs(), mesh.dofs());
  const auto ref = states_from_dofs(mesh, Eigen::VectorXd::Zero(mesh.dofs()));
  ElementResponse r;
  for (size_t e = 0; e < mesh.quads.size(); ++e) {
    const int ei = static_cast<int>(e);
    element.compute(mesh.geometry(ei), element_states(mesh, ref, ei), law, Kinematics::kLinear,
                    {false, true}, r);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        K.block<kShellNodeDofs, kShellNodeDofs>(kShellNodeDofs * mesh.quads[e][a],
                                                kShellNodeDofs * mesh.quads[e][b]) +=
            r.tangent.block<kShellNodeDofs, kShellNodeDofs>(kShellNodeDofs * a, kShellNodeDofs * b);
  }
  return K;
}

// Dense tangent and internal force (nonlinear mode) at the given node states.
inline void assemble_nonlinear(const ShellElement& element, const ShellMesh& mesh,
                               const std::vector<NodeState>& states, const ShellLaw& law,
                               Eigen::MatrixXd& K, Eigen::VectorXd& f) {
  K = Eigen::MatrixXd::Zero(mesh.dofs(), mesh.dofs());
  f = Eigen::VectorXd::Zero(mesh.dofs());
  ElementResponse r;
  for (size_t e = 0; e < mesh.quads.size(); ++e) {
    const int ei = static_cast<int>(e);
    element.compute(mesh.geometry(ei), element_states(mesh, states, ei), law,
                    Kinematics::kNonlinear, {}, r);
    for (int a = 0; a < 4; ++a) {
      const int ga = kShellNodeDofs * mesh.quads[e][a];
      f.segment<kShellNodeDofs>(ga) += r.force.segment<kShellNodeDofs>(kShellNodeDofs * a);
      for (int b = 0; b < 4; ++b)
        K.block<kShellNodeDofs, kShellNodeDofs>(ga, kShellNodeDofs * mesh.quads[e][b]) +=
            r.tangent.block<kShellNodeDofs, kShellNodeDofs>(kShellNodeDofs * a, kShellNodeDofs * b);
    }
  }
}

// Solves K q = f with q(dof) = value for the prescribed dofs.
inline Eigen::VectorXd solve_dirichlet(const Eigen::MatrixXd& K, const Eigen::VectorXd& f,
                                       const std::map<int, double>& prescribed) {
  const int n = static_cast<int>(K.rows());
  std::vector<int> free;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    const auto it = prescribed.find(i);
    if (it == prescribed.end())
      free.push_back(i);
    else
      q(i) = it->second;
  }
  const int m = static_cast<int>(free.size());
  Eigen::MatrixXd Kff(m, m);
  Eigen::VectorXd rhs(m);
  const Eigen::VectorXd Kq = K * q;
  for (int a = 0; a < m; ++a) {
    rhs(a) = f(free[a]) - Kq(free[a]);
    for (int b = 0; b < m; ++b) Kff(a, b) = K(free[a], free[b]);
  }
  const Eigen::VectorXd qf = Kff.ldlt().solve(rhs);
  for (int a = 0; a < m; ++a) q(free[a]) = qf(a);
  return q;
}

}  // namespace si::test
