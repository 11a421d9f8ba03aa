#include "model/imported_mesh_sets.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "model/mesh_topology.hpp"

namespace si {
namespace {

int nearest_to_axis(const Mesh& mesh) {
  int best = 0;
  for (int n = 1; n < mesh.num_nodes(); ++n) {
    const Vector3d& p = mesh.nodes[n];
    const Vector3d& b = mesh.nodes[best];
    const double r = p.x() * p.x() + p.y() * p.y(), rb = b.x() * b.x() + b.y() * b.y();
    if (r < rb || (r == rb && p.z() > b.z())) best = n;
  }
  return best;
}

}  // namespace

void add_imported_mesh_sets(Mesh& mesh, Symmetry symmetry) {
  if (mesh.node_sets.count("apex") == 0) set_node_set(mesh, "apex", {nearest_to_axis(mesh)});
  if (mesh.node_sets.at("apex").size() != 1)
    throw_input("the physical group 'apex' must hold one node (the indentation or load point)");
  set_node_set(mesh, "edge", boundary_nodes(mesh));
  if (symmetry != Symmetry::kQuarter) return;
  Vector3d lo = mesh.nodes.front(), hi = lo;
  for (const Vector3d& p : mesh.nodes) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double tol = 1e-9 * (hi - lo).norm();
  if (lo.x() < -tol || lo.y() < -tol)
    throw_input("a quarter model is the part x >= 0, y >= 0, but the mesh reaches x = " +
                std::to_string(lo.x()) + ", y = " + std::to_string(lo.y()) + " mm");
  set_node_set(mesh, "symmetry_x",
               nodes_where(mesh, [&](const Vector3d& p) { return std::abs(p.x()) <= tol; }));
  set_node_set(mesh, "symmetry_y",
               nodes_where(mesh, [&](const Vector3d& p) { return std::abs(p.y()) <= tol; }));
}

}  // namespace si
