#include "model/mesh.hpp"

#include <algorithm>
#include <cmath>

namespace si {

std::array<Vector3d, 4> element_corners(const Mesh& mesh, int e) {
  const auto& el = mesh.elements[e];
  return {mesh.nodes[el[0]], mesh.nodes[el[1]], mesh.nodes[el[2]], mesh.nodes[el[3]]};
}

Vector3d element_normal(const Mesh& mesh, int e) {
  const auto x = element_corners(mesh, e);
  const Vector3d n = (x[2] - x[0]).cross(x[3] - x[1]);
  const double len = n.norm();
  return len > 0 ? Vector3d(n / len) : Vector3d::Zero();
}

double element_area(const Mesh& mesh, int e) {
  const auto x = element_corners(mesh, e);
  const double g = 1.0 / std::sqrt(3.0);
  double area = 0;
  for (double xi : {-g, g}) {
    for (double eta : {-g, g}) {
      // Derivatives of the bilinear map x = sum N_a x_a, N_a = (1 +- xi)(1 +- eta)/4.
      const Vector3d x_xi = 0.25 * ((1 - eta) * (x[1] - x[0]) + (1 + eta) * (x[2] - x[3]));
      const Vector3d x_eta = 0.25 * ((1 - xi) * (x[3] - x[0]) + (1 + xi) * (x[2] - x[1]));
      area += x_xi.cross(x_eta).norm();  // Gauss weights are 1
    }
  }
  return area;
}

double mesh_area(const Mesh& mesh) {
  double area = 0;
  for (int e = 0; e < mesh.num_elements(); ++e) area += element_area(mesh, e);
  return area;
}

void compute_directors_from_elements(Mesh& mesh) {
  mesh.directors.assign(mesh.nodes.size(), Vector3d::Zero());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const Vector3d weighted = element_normal(mesh, e) * element_area(mesh, e);
    for (int n : mesh.elements[e]) mesh.directors[n] += weighted;
  }
  for (Vector3d& d : mesh.directors) {
    const double len = d.norm();
    d = len > 0 ? Vector3d(d / len) : Vector3d::Zero();
  }
}

void flip_orientation(Mesh& mesh) {
  for (auto& el : mesh.elements) std::swap(el[1], el[3]);
  for (Vector3d& d : mesh.directors) d = -d;
}

std::vector<int> nodes_where(const Mesh& mesh,
                             const std::function<bool(const Vector3d&)>& predicate) {
  std::vector<int> selected;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (predicate(mesh.nodes[n])) selected.push_back(n);
  }
  return selected;
}

void set_node_set(Mesh& mesh, const std::string& name, std::vector<int> indices) {
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  mesh.node_sets[name] = std::move(indices);
}

}  // namespace si
