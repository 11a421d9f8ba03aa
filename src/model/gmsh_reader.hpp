// Reader of Gmsh MSH files of quadrilateral shell meshes: versions 4.1 (text and binary) and 2.2
// (text) (format: https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format).
//
// What becomes of the file:
//  * 4-node quadrangles (type 3) are the elements; nodes are renumbered densely in the order of
//    their Gmsh tags, keeping those of quadrangles only.
//  * Physical groups become node sets named after the group ("physical_<dim>_<tag>" when it has
//    no name): points and lines give the nodes of their elements, surfaces give their nodes and
//    also an element set (a loaded face, the contact face).
//  * Directors are the area-weighted averages of the element normals
//    (compute_directors_from_elements), so they point to the side from which the node order is
//    counter-clockwise; the outer face (the indenter's side, the top ply) is that side.
//
// Refused, with the file, the line (text) or byte (binary) and the Gmsh element or node tag:
// an unsupported version or byte order, triangles (there is no triangle shell), higher-order or
// volume elements, unknown element types, truncated sections, counts that cannot fit in the
// file (nothing is allocated beyond what the file could describe), node tags defined twice or
// referenced but not defined, physical-group nodes outside the quadrangles, a non-manifold edge,
// neighbours with opposite orientation (unless `reorient`), a surface that cannot be oriented,
// and degenerate, inverted or badly distorted elements (check_element, mesh_quality.hpp).
#pragma once

#include <string>
#include <vector>

#include "model/mesh.hpp"

namespace si {

struct GmshReadOptions {
  // Reverse elements whose orientation disagrees with their neighbours' (propagated from the
  // lowest-tagged element of each connected piece) instead of refusing the file; each reversal
  // is reported in ImportedMesh::warnings.
  bool reorient = false;
  // Reverse every element after reading: the directors then point to the other side.
  bool flip = false;
};

struct ImportedMesh {
  Mesh mesh;
  std::vector<std::string> warnings;
};

ImportedMesh read_gmsh_mesh(const std::string& path, const GmshReadOptions& options = {});

}  // namespace si
