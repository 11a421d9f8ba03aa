// Nodal director frames of the degenerated shell (paper eqs 36-39, Fig. 3; Bathe, "Finite
// Element Procedures", 1996, sec. 5.4). Each node carries a unit director d and two unit axes
// v1, v2 with (v1, v2, d) right-handed orthonormal; its two rotational dofs are rotations about
// the CURRENT v1 and v2. A rotation increment theta = a v1 + b v2 changes the director by
// delta d = theta x d = -a v2 + b v1, i.e. the paper's R_i = [-v2, v1] (eq 39).
#pragma once

#include "core/linalg.hpp"

namespace si {

struct NodeState {
  Vector3d u = Vector3d::Zero();    // displacement of the mid-surface node from its reference, mm
  Vector3d d = Vector3d::UnitZ();   // current unit director
  Vector3d v1 = Vector3d::UnitX();  // current first rotation axis, unit, orthogonal to d
  Vector3d v2 = Vector3d::UnitY();  // current second rotation axis, v2 = d x v1
};

// Reference frame of a node with reference director D (normalised here; |D| must be 1 within
// 1e-6, else an input error):  V1 = (e2 x D) / |e2 x D|, V2 = D x V1 (Bathe, sec. 5.4, the
// construction the paper's Fig. 3 flowchart encodes; the figure itself is not in the paper's
// text). If D is parallel to e2 (|e2 x D| < 1e-8) then V1 = e3 (Bathe's rule), giving
// V2 = D x e3. u = 0.
NodeState reference_node_state(const Vector3d& D);

// Rodrigues' formula: the rotation matrix exp(skew(theta)), accurate for small |theta| too.
Matrix3d rotation_matrix(const Vector3d& theta);

// Multiplicative update of a node's rotation: Q = exp(skew(a v1 + b v2)) with the node's current
// axes, applied to d, v1 and v2. Exact for any accumulated rotation (no angle is stored).
void rotate_node(NodeState& node, double a, double b);

}  // namespace si
