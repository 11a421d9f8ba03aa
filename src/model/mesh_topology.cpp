#include "model/mesh_topology.hpp"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace si {
namespace {

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

// Elements around each undirected edge, in element order.
std::unordered_map<std::uint64_t, std::vector<int>> edge_elements(const Mesh& mesh) {
  std::unordered_map<std::uint64_t, std::vector<int>> edges;
  edges.reserve(2 * mesh.elements.size() + 8);
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto& el = mesh.elements[e];
    for (int k = 0; k < 4; ++k) edges[edge_key(el[k], el[(k + 1) % 4])].push_back(e);
  }
  return edges;
}

// +1 if element e traverses edge (a, b) from a to b, -1 if from b to a.
int direction(const Mesh& mesh, int e, int a, int b) {
  const auto& el = mesh.elements[e];
  for (int k = 0; k < 4; ++k)
    if (el[k] == a && el[(k + 1) % 4] == b) return 1;
  return -1;
}

}  // namespace

std::optional<NonManifoldEdge> find_non_manifold_edge(const Mesh& mesh) {
  std::optional<NonManifoldEdge> worst;
  for (const auto& [key, elements] : edge_elements(mesh)) {
    if (elements.size() <= 2) continue;
    if (worst && worst->elements.front() <= elements.front()) continue;
    worst =
        NonManifoldEdge{static_cast<int>(key >> 32), static_cast<int>(key & 0xffffffffu), elements};
  }
  return worst;
}

OrientationFix consistent_orientation(const Mesh& mesh) {
  const auto edges = edge_elements(mesh);
  const int ne = mesh.num_elements();
  std::vector<int> sign(ne, 0);  // +1 keep, -1 reverse, 0 not reached yet
  OrientationFix fix;
  std::vector<int> queue;
  for (int start = 0; start < ne; ++start) {
    if (sign[start] != 0) continue;
    sign[start] = 1;
    queue.assign(1, start);
    while (!queue.empty()) {
      const int e = queue.back();
      queue.pop_back();
      const auto& el = mesh.elements[e];
      for (int k = 0; k < 4; ++k) {
        const int a = el[k], b = el[(k + 1) % 4];
        for (int other : edges.at(edge_key(a, b))) {
          if (other == e) continue;
          // Opposite traversal after the chosen reversals is consistent.
          const int required = -sign[e] * direction(mesh, e, a, b) * direction(mesh, other, a, b);
          if (sign[other] == 0) {
            sign[other] = required;
            queue.push_back(other);
          } else if (sign[other] != required) {
            fix.conflict = std::pair{std::min(e, other), std::max(e, other)};
            return fix;
          }
        }
      }
    }
  }
  for (int e = 0; e < ne; ++e)
    if (sign[e] < 0) fix.flip.push_back(e);
  return fix;
}

void reverse_elements(Mesh& mesh, const std::vector<int>& elements) {
  for (int e : elements) std::swap(mesh.elements[e][1], mesh.elements[e][3]);
}

std::vector<std::array<int, 2>> boundary_segments(const Mesh& mesh) {
  const auto edges = edge_elements(mesh);
  std::vector<std::array<int, 2>> out;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto& el = mesh.elements[e];
    for (int k = 0; k < 4; ++k) {
      const int a = el[k], b = el[(k + 1) % 4];
      if (edges.at(edge_key(a, b)).size() == 1) out.push_back({a, b});
    }
  }
  return out;
}

std::vector<int> boundary_nodes(const Mesh& mesh) {
  std::vector<int> nodes;
  for (const auto& s : boundary_segments(mesh)) nodes.insert(nodes.end(), s.begin(), s.end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace si
