// Reader of Gmsh ASCII MSH 4.1 files of quadrilateral shell meshes
// (format: https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format, section "MSH file format
// version 4.1").
//
// Read: $MeshFormat (must be 4.1 ASCII), $PhysicalNames, $Entities, $Nodes, $Elements; other
// sections are skipped. 4-node quadrangles (type 3) become the elements. Points (type 15) and
// lines (types 1, 8) on entities that carry physical groups become node sets named after the
// group ("physical_<dim>_<tag>" when the group has no name); other point/line elements are
// ignored. Any other surface element (triangles, 8/9-node quadrangles) or volume element is
// refused. Nodes are renumbered densely in the order of their Gmsh tags, keeping only those of
// quadrangles; directors are the averaged element normals (compute_directors_from_elements),
// so the side the directors point to is the one from which Gmsh's node order is
// counter-clockwise - use flip_orientation (mesh.hpp) to turn it over.
//
// Errors (si::Error, kind kInput) name the file and the line; the mesh is validated with
// check_mesh, including consistent orientation of neighbouring elements.
#pragma once

#include <string>

#include "model/mesh.hpp"

namespace si {

Mesh read_gmsh_msh4(const std::string& path);

}  // namespace si
