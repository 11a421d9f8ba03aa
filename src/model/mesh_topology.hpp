// Edge topology of a quadrilateral surface mesh: non-manifold edges, consistent orientation of
// the elements, and the boundary (element sides that belong to one element only). Used to
// validate imported meshes and to find the edges a default support applies to.
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include "model/mesh.hpp"

namespace si {

// An edge (nodes a < b) shared by more than two elements.
struct NonManifoldEdge {
  int a = 0, b = 0;
  std::vector<int> elements;
};

// The first non-manifold edge (lowest element index), if any.
std::optional<NonManifoldEdge> find_non_manifold_edge(const Mesh& mesh);

// Which elements to reverse so that every two elements sharing an edge traverse it in opposite
// directions, keeping the orientation of the lowest-numbered element of each connected piece.
// `conflict` is set (and `flip` meaningless) if no such choice exists: the surface is not
// orientable (a Moebius strip) - the pair of elements where the contradiction closed.
// Requires a manifold mesh (find_non_manifold_edge).
struct OrientationFix {
  std::vector<int> flip;
  std::optional<std::pair<int, int>> conflict;
};
OrientationFix consistent_orientation(const Mesh& mesh);

// Reverses the node order of the listed elements (directors are left alone).
void reverse_elements(Mesh& mesh, const std::vector<int>& elements);

// Element sides that belong to one element only, as (node, next node) in that element's order.
std::vector<std::array<int, 2>> boundary_segments(const Mesh& mesh);

// Sorted nodes of the boundary segments.
std::vector<int> boundary_nodes(const Mesh& mesh);

}  // namespace si
