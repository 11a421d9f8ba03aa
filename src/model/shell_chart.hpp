// Additive coordinates for the shell's free dofs ("chart"), so that KINSOL and the continuation
// library, which add vectors, can work on a shell whose rotations compose multiplicatively.
//
// Coordinates x (one per free dof, DofMap equation order): the translations u (mm) and, per
// node, the components (a, b) of a rotation vector theta = a V1 + b V2 on the node's BASE axes;
// the node's frame is exp(skew(theta)) applied to its base frame (D, V1, V2). The base is the
// reference frame unless the chart was re-based (rebase()); with the reference base this is
// exactly the state the element's linear mode reads back (shell_element.hpp) and the one
// rotate_node(reference, a, b) gives. It covers every director with |theta| < pi, and is
// singular at |theta| = pi (every theta of that length gives d = -D: T below loses rank), so a
// path on which a node turns further re-bases the chart on the way (rebase()).
//
// The assembled tangent K is the derivative of the residual r (rotation rows = components of the
// nodal moment on the CURRENT v1, v2) with respect to increments q about the current axes
// (director.hpp). The derivative with respect to the chart is then (Simo & Vu-Quoc 1986, the
// tangent of the exponential map)
//     dr/dx = K T(x) + D(x, r),
// where, per node, omega = J(theta) [V1 V2] (da, db) is the spatial angular velocity of a chart
// increment (J = the left Jacobian of SO(3)), T = [v1 v2]^T J [V1 V2] is its projection on the
// current axes, and D is the drilling part omega . d, which turns the current axes about d and
// so changes the rotation rows' components: d r_1 = (omega.d) r_2, d r_2 = -(omega.d) r_1.
// T is the identity at theta = 0. The rows differentiated by D are those that are components of
// a vector on the current axes: the INTERNAL force's; a load whose generalised forces on the
// rotation rows are constant (NodalMoment, loads.hpp) has no such term, so r below is f_int.
#pragma once

#include <vector>

#include "core/sparse.hpp"
#include "model/dof_map.hpp"
#include "model/mesh.hpp"
#include "shell/director.hpp"

namespace si {

class ShellChart {
 public:
  // Keeps references to mesh and dof map.
  ShellChart(const Mesh& mesh, const DofMap& dofs);

  int size() const { return dofs_.num_free(); }

  // Node states at chart point x; prescribed translations at prescribed_scale * value,
  // prescribed rotation components at zero.
  void states(const Eigen::VectorXd& x, double prescribed_scale, std::vector<NodeState>& out) const;

  // The chart point of a state (inverse of states(); the drilling orientation of v1, v2 is
  // ignored). Throws if a node has rotated by pi or more from its base, or about its director.
  Eigen::VectorXd coordinates(const std::vector<NodeState>& state) const;

  // The rotation vector theta (|theta| < pi, normal to D) that takes a node's reference director
  // D to d, and its reference frame; with the reference base its components on (V1, V2) are the
  // node's chart coordinates. Throws a numerical error at a turn of pi or more.
  Vector3d rotation_vector(int node, const Vector3d& d) const;
  const NodeState& reference(int node) const { return reference_[node]; }

  // Re-basing: every node whose chart rotation at x exceeds max_angle (rad) takes its frame at x
  // as its new base, and its rotation coordinates in x become 0; the states at x are unchanged
  // (the translations are not re-based: u stays the displacement from the reference). Returns
  // the number of nodes re-based. base()/set_base() save and restore the base frames.
  int rebase(Eigen::VectorXd& x, double max_angle);
  const std::vector<NodeState>& base() const { return base_; }
  void set_base(std::vector<NodeState> base);

  // In place: K (its first num_free() columns are the shell's free dofs, in equation order; it
  // may have more rows and columns, e.g. Lagrange multipliers) becomes K T(x), then the drilling
  // term D(x, r) is added to the shell's rotation rows. r is the internal force at x restricted to
  // the free dofs (rotation rows on the current axes). The two rotation columns of a node must have
  // the same sparsity pattern (true for assembled shell blocks), and the node's diagonal 2x2
  // rotation block must be in the pattern.
  // The 2x2 blocks T(x) of the transform, one per node with a free rotation component
  // (eq_b = -1 or eq_a = -1 when that component is prescribed; T is then diagonal there). With
  // them a caller can form T^T K T, the chart Hessian up to terms that vanish at equilibrium.
  struct RotationBlock {
    int eq_a = -1, eq_b = -1;
    Matrix2d T = Matrix2d::Identity();
  };
  // Returns the blocks T it applied.
  std::vector<RotationBlock> to_chart_jacobian(const Eigen::VectorXd& x, const Eigen::VectorXd& r,
                                               SparseMatrix& K) const;
  // The block-diagonal transform T of n free dofs from the blocks: identity on translations, the
  // 2x2 blocks on each node's rotation coordinates (T' J is the chart Hessian at equilibrium).
  static SparseMatrix transform(int n, const std::vector<RotationBlock>& blocks);

 private:
  struct NodeRotation {
    int node = 0;
    int eq_a = -1, eq_b = -1;  // equations of the rotation dofs, -1 if prescribed
  };
  Vector3d theta(const Eigen::VectorXd& x, const NodeRotation& r) const;
  // The rotation vector normal to D that takes director D to d (node: for the error message).
  static Vector3d turn(int node, const Vector3d& D, const Vector3d& d);
  // T of the header and the drilling row d^T W of one node at x.
  void node_transform(const Eigen::VectorXd& x, const NodeRotation& r, Matrix2d& T,
                      Eigen::RowVector2d& drill) const;

  const Mesh& mesh_;
  const DofMap& dofs_;
  std::vector<NodeState> reference_;
  std::vector<NodeState> base_;  // the frames the rotation coordinates start from (rebase())
  std::vector<NodeRotation> rotations_;  // nodes with at least one free rotation dof
};

// The left Jacobian of SO(3): exp(skew(theta + dtheta)) = exp(skew(J dtheta)) exp(skew(theta))
// to first order. J = I + (1 - cos t)/t^2 S + (t - sin t)/t^3 S^2, S = skew(theta), t = |theta|.
Matrix3d so3_left_jacobian(const Vector3d& theta);

}  // namespace si
