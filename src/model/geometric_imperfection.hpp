// A geometric imperfection added to a mesh (docs/case-file.md `path.imperfection`): the nodes move
// by given translations, and the directors turn with the surface.
#pragma once

#include <Eigen/Dense>

#include <vector>

#include "model/mesh.hpp"
#include "model/supports.hpp"

namespace si {

// Moves node n by translations.row(n) (mm; rows = the mesh's nodes, 3 columns) and turns its
// director by the change of the area-weighted element normals at the node
// (compute_directors_from_elements of the shape before and after): d' = (d + n1 - n0) / |...|.
// Directors given exactly (the built-in surfaces' normals) so stay normal to the imperfect surface
// to first order in the translations, and a mesh whose directors are its element normals gets
// exactly those of the moved mesh. Throws std::invalid_argument on a size mismatch.
void add_imperfection(Mesh& mesh, const Eigen::MatrixXd& translations);

// Puts back into each symmetry plane of `supports` (kSymmetryPlane) the directors of the plane's
// nodes: the component along the plane's normal is removed and the director renormalised. After
// add_imperfection the turn n1 - n0 at such a node comes from the elements on one side of the
// plane only (the mirrored half is not meshed), so it leaves the plane although a symmetric
// imperfection's exact normal lies in it; the supports refuse a director off its plane. Throws
// std::out_of_range for a support naming a node set the mesh lacks.
void keep_directors_in_symmetry_planes(Mesh& mesh, const std::vector<Support>& supports);

}  // namespace si
