// A shell surface mesh of 4-node quadrilaterals: the reference mid-surface, a unit director per
// node and named node sets. It is a value type; generators and the Gmsh reader fill it, and
// check_mesh (mesh_quality.hpp) validates it.
//
// Conventions, relied upon by the shell elements:
//  * nodes are reference mid-surface positions in mm;
//  * directors[n] is the unit reference normal at node n: the exact surface normal where the
//    generator knows the surface, else the area-weighted average of the element normals;
//  * elements list their nodes counter-clockwise seen from the tip of the director, so the
//    element normal (x_xi cross x_eta of the bilinear map) agrees with the directors;
//  * every node set holds sorted, unique node indices; element sets (surface regions of an
//    imported mesh, e.g. a loaded face) hold sorted, unique element indices.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/linalg.hpp"

namespace si {

struct Mesh {
  std::vector<Vector3d> nodes;
  std::vector<Vector3d> directors;
  std::vector<std::array<int, 4>> elements;
  std::map<std::string, std::vector<int>> node_sets;
  std::map<std::string, std::vector<int>> element_sets;

  int num_nodes() const { return static_cast<int>(nodes.size()); }
  int num_elements() const { return static_cast<int>(elements.size()); }
};

// The four corner positions of element e.
std::array<Vector3d, 4> element_corners(const Mesh& mesh, int e);

// Unit normal of element e at its centre: the cross product of the diagonals, which equals
// x_xi cross x_eta of the bilinear map at xi = eta = 0. Zero vector if the element has no area.
Vector3d element_normal(const Mesh& mesh, int e);

// Area of the bilinear surface of element e (2 x 2 Gauss rule on |x_xi cross x_eta|).
double element_area(const Mesh& mesh, int e);

// Sum of the element areas.
double mesh_area(const Mesh& mesh);

// Replaces the directors by the normalised sum of area-weighted element normals at each node.
// For a node used by no element, or where the normals cancel, the director is set to zero
// (check_mesh then reports it).
void compute_directors_from_elements(Mesh& mesh);

// Reverses the node order of every element and the directors: the mesh seen from the other side.
void flip_orientation(Mesh& mesh);

// Sorted indices of the nodes whose position satisfies the predicate, for user node sets.
std::vector<int> nodes_where(const Mesh& mesh,
                             const std::function<bool(const Vector3d&)>& predicate);

// Stores `indices` as node set `name`, sorted and without repeats.
void set_node_set(Mesh& mesh, const std::string& name, std::vector<int> indices);

}  // namespace si
