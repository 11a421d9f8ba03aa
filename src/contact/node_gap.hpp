// The gap of one shell node and its derivatives in the node's five dofs (u1 u2 u3 along the
// global axes, then rotations q1, q2 about the node's current v1, v2; director.hpp).
//
// The contact point is p = X + u + c d: the node's mid-surface point moved along the current
// director by the offset c of the contact face (t_top for the laminate's outer face, 0 for the
// mid-surface as in the paper). With a = ds/dp and A = d2s/dp2 of travel_gap.hpp, E = [-v2, v1]
// (so that delta d = E q), V = [v1 v2] and m = d x a:
//     gap      g = s(p) - h
//     gradient G = [a ; c E^T a]                      (G . delta = delta g)
//     derivative of G under an increment (delta u, q) about the current axes:
//       dG = [A, c A E ; c E^T A, c^2 E^T A E + c N],
//       N_ab = V_b . (v_a x m) + E_b . (a x v_a)      (the frame turns with the increment)
// The contact force on the node is lambda G (force lambda a, moment components c lambda E^T a).
//
// Linearised (linear kinematics, the paper's eqs 73-80): G is frozen at the reference state and
// the gap is s(P) - h + G0 . (u, theta . V1, theta . V2), P = X + c D; exactly linear in the
// dofs and in h, as the linear fast path needs.
#pragma once

#include "contact/indenter.hpp"
#include "shell/director.hpp"

namespace si {

using Vector5d = Eigen::Matrix<double, 5, 1>;
using Matrix5d = Eigen::Matrix<double, 5, 5>;

struct NodeGap {
  bool hits = false;        // false: the contact point is beside the indenter's path (no contact)
  double gap = 0;           // mm
  double touch_travel = 0;  // s(p), the travel at which the indenter reaches the point
  Vector5d gradient = Vector5d::Zero();
  Matrix5d gradient_derivative = Matrix5d::Zero();  // dG, only if asked for (not symmetric)
};

struct NodeContactGeometry {
  Vector3d X = Vector3d::Zero();  // reference mid-surface position, mm
  double offset = 0;              // c, mm, along the director
};

// Exact gap at travel h; `guess` is a travel near s(p) (travel_gap.hpp).
NodeGap node_gap(const Indenter& indenter, const Vector3d& direction,
                 const NodeContactGeometry& node, const NodeState& state, double travel,
                 double guess, bool want_derivative);

// The gap linearised about the reference state `reference` (u = 0, d = D): value at the chart
// coordinates (u, a, b) of the node (shell_chart.hpp), gradient G0, no derivative.
NodeGap linearized_node_gap(const Indenter& indenter, const Vector3d& direction,
                            const NodeContactGeometry& node, const NodeState& reference,
                            const Vector5d& coordinates, double travel);

// The gap of the node's contact point to a fixed plane {y : normal . y = level} on the side the
// unit normal points to (a rigid support frame under the shell, indentation/support_frame.hpp):
//     g = normal . (X + u + c d) - level,   G = [n ; c E^T n],   dG as above with a = n, A = 0.
// Always `hits`; touch_travel is not used.
NodeGap plane_gap(const Vector3d& normal, double level, const NodeContactGeometry& node,
                  const NodeState& state, bool want_derivative);

// The plane gap linearised about the reference state: g(reference) + G0 . coordinates.
NodeGap linearized_plane_gap(const Vector3d& normal, double level, const NodeContactGeometry& node,
                             const NodeState& reference, const Vector5d& coordinates);

}  // namespace si
