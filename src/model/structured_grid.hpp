// Building blocks of the mesh generators: a structured patch of quadrilaterals and the merging
// of patches along shared boundaries (multi-block meshes such as the disk O-grid).
#pragma once

#include <functional>

#include "model/mesh.hpp"

namespace si {

// An n_u x n_v patch: node (i, j), 0 <= i <= n_u, 0 <= j <= n_v, has index i + (n_u + 1) j and
// position position(i, j). Elements are (i,j), (i+1,j), (i+1,j+1), (i,j+1): counter-clockwise in
// the (u, v) parameter plane, so their normal points along x_u cross x_v. Directors are left
// empty; node sets too.
Mesh structured_grid(int n_u, int n_v, const std::function<Vector3d(int, int)>& position);

// Appends the nodes and elements of `part` to `mesh`; a node of `part` closer than `tolerance`
// to a node already in `mesh` is merged with it. Directors are appended if both meshes have
// them; node sets of `part` are not copied (generators define their sets on the final mesh).
void merge_into(Mesh& mesh, const Mesh& part, double tolerance);

}  // namespace si
