#include "model/structured_grid.hpp"

#include "core/error.hpp"
#include "model/point_locator.hpp"

namespace si {

Mesh structured_grid(int n_u, int n_v, const std::function<Vector3d(int, int)>& position) {
  SI_REQUIRE(n_u >= 1 && n_v >= 1, "a structured patch needs at least one element each way");
  Mesh mesh;
  const auto id = [n_u](int i, int j) { return i + (n_u + 1) * j; };
  mesh.nodes.reserve(static_cast<size_t>((n_u + 1) * (n_v + 1)));
  for (int j = 0; j <= n_v; ++j) {
    for (int i = 0; i <= n_u; ++i) mesh.nodes.push_back(position(i, j));
  }
  for (int j = 0; j < n_v; ++j) {
    for (int i = 0; i < n_u; ++i) {
      mesh.elements.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return mesh;
}

void merge_into(Mesh& mesh, const Mesh& part, double tolerance) {
  PointLocator locator(tolerance);
  for (int n = 0; n < mesh.num_nodes(); ++n) locator.insert(mesh.nodes[n], n);
  const bool with_directors =
      mesh.directors.size() == mesh.nodes.size() && part.directors.size() == part.nodes.size();
  if (!with_directors) mesh.directors.clear();

  std::vector<int> new_index(part.nodes.size());
  for (int n = 0; n < part.num_nodes(); ++n) {
    int found = locator.find(part.nodes[n]);
    if (found < 0) {
      found = mesh.num_nodes();
      mesh.nodes.push_back(part.nodes[n]);
      if (with_directors) mesh.directors.push_back(part.directors[n]);
      locator.insert(part.nodes[n], found);
    }
    new_index[n] = found;
  }
  for (const auto& el : part.elements) {
    mesh.elements.push_back(
        {new_index[el[0]], new_index[el[1]], new_index[el[2]], new_index[el[3]]});
  }
}

}  // namespace si
