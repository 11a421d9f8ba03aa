// Supports and prescribed translations on named node sets, turned into prescribed dofs.
//
// Dof order per node (shell/shell_element.hpp): u1 u2 u3 along the global axes, then the
// rotations about the node's reference axes v1 = (e2 x D)/|e2 x D|, v2 = D x v1. Definitions:
//  - kClamped: all 5 dofs zero.
//  - kHinged: the 3 translations zero, rotations free.
//  - kSimplySupported: the transverse deflection u.D zero, in-plane translations and rotations
//    free (the "hard" SS of plate theory). A constraint on u.D is a single dof only if D is a
//    global axis, so every node's director must be within 1e-8 of +-e_x, +-e_y or +-e_z;
//    otherwise an input error says so (use kHinged or kFixedDofs). The in-plane rigid-body
//    motions are NOT suppressed: the caller adds symmetry planes or kFixedDofs on a few nodes.
//  - kSymmetryPlane with normal e_k (plane_axis = k): u_k = 0, and the director must stay in the
//    plane. A rotation increment about axis a moves d by a x d; of the two rotation dofs the one
//    whose motion has a component along e_k is fixed. With the reference frame, v1 x D = -v2 and
//    v2 x D = v1, so the fixed dof is the one whose *other* axis is +-e_k. If that component is
//    neither ~0 nor ~1 (within 1e-8) for either dof, or D itself is not in the plane, the nodal
//    frame is not aligned with the plane and an input error says so. Rotating about the axis
//    that is +-e_k keeps it +-e_k, so the condition holds at every later state too.
//  - kFixedDofs: the listed local dofs (0..4) zero.
// A node in several supports gets the union of their constraints.
#pragma once

#include <string>
#include <vector>

#include "model/dof_map.hpp"
#include "model/mesh.hpp"

namespace si {

enum class SupportKind { kClamped, kHinged, kSimplySupported, kSymmetryPlane, kFixedDofs };

struct Support {
  SupportKind kind = SupportKind::kClamped;
  std::string node_set;
  int plane_axis = -1;          // kSymmetryPlane only: 0, 1, 2 for the plane normal e_x, e_y, e_z
  std::vector<int> local_dofs;  // kFixedDofs only: dofs 0..4 of every node of the set
};

// Translation `component` (0, 1, 2 = global x, y, z) of every node of the set equals `value` (mm)
// at load factor 1; the static solver scales it with the load factor like the loads.
struct PrescribedDisplacement {
  std::string node_set;
  int component = 0;
  double value = 0;
};

// All prescribed dofs of the supports and prescribed displacements. Throws an input error for an
// unknown node set (listing the available ones), a bad axis/dof/component, a node whose frame
// does not fit its support (see above), or a dof prescribed twice with different values.
std::vector<PrescribedDof> prescribed_dofs(
    const Mesh& mesh, const std::vector<Support>& supports,
    const std::vector<PrescribedDisplacement>& displacements);

// Convenience: the dof map of a mesh with these supports and prescribed displacements.
DofMap make_dof_map(const Mesh& mesh, const std::vector<Support>& supports,
                    const std::vector<PrescribedDisplacement>& displacements = {});

}  // namespace si
