// A geometric imperfection added to a mesh (docs/case-file.md `path.imperfection`): the nodes move
// by given translations, and the directors turn with the surface.
#pragma once

#include <Eigen/Dense>

#include "model/mesh.hpp"

namespace si {

// Moves node n by translations.row(n) (mm; rows = the mesh's nodes, 3 columns) and turns its
// director by the change of the area-weighted element normals at the node
// (compute_directors_from_elements of the shape before and after): d' = (d + n1 - n0) / |...|.
// Directors given exactly (the built-in surfaces' normals) so stay normal to the imperfect surface
// to first order in the translations, and a mesh whose directors are its element normals gets
// exactly those of the moved mesh. Throws std::invalid_argument on a size mismatch.
void add_imperfection(Mesh& mesh, const Eigen::MatrixXd& translations);

}  // namespace si
