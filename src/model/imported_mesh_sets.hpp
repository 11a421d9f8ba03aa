// The node sets every shell model relies on (analysis/shell_model.hpp), made for a mesh read from
// a file: "apex" (the file's physical group of that name, else the node nearest to the z axis,
// the highest on a tie), "edge" (the nodes on the boundary) and, for a quarter model of the part
// x >= 0, y >= 0, "symmetry_x" and "symmetry_y" (the nodes on x = 0 and y = 0, within 1e-9 of the
// mesh's size; nodes at x < 0 or y < 0 are refused).
#pragma once

#include "model/mesh.hpp"
#include "model/symmetry.hpp"

namespace si {

void add_imported_mesh_sets(Mesh& mesh, Symmetry symmetry);

}  // namespace si
