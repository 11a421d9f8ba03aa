#include "model/hemisphere_mesh.hpp"

#include <cmath>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "model/mesh_quality.hpp"
#include "model/structured_grid.hpp"

namespace si {
namespace {

constexpr double kHoleDeg = 18;  // MacNeal & Harder 1985: hole of 18 deg about the pole

// Unit vector at azimuth `psi` (from +x towards +y) and latitude `lat`; the quarter's sides are
// put exactly on their planes (cos(pi/2) is not exactly zero).
Vector3d unit_sphere(int i, int n, double lat) {
  const double psi = kPi / 2 * i / n;
  const double c = i == n ? 0.0 : std::cos(psi);
  const double s = i == 0 ? 0.0 : std::sin(psi);
  return Vector3d(std::cos(lat) * c, std::cos(lat) * s, std::sin(lat));
}

}  // namespace

Mesh hemisphere_mesh(double radius, int n) {
  if (!(std::isfinite(radius) && radius > 0)) {
    throw_input("must be positive", {"", "radius", std::to_string(radius)});
  }
  if (n < 1) throw_input("needs at least one element", {"", "n", std::to_string(n)});
  const double top = (90 - kHoleDeg) * kPi / 180;
  // u = azimuth, v = latitude: x_psi cross x_lat points outward.
  Mesh mesh = structured_grid(
      n, n, [&](int i, int j) { return Vector3d(radius * unit_sphere(i, n, top * j / n)); });
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) mesh.directors.push_back(unit_sphere(i, n, top * j / n));
  }
  const auto id = [n](int i, int j) { return i + (n + 1) * j; };
  std::vector<int> sym_x, sym_y, hole, equator;
  for (int k = 0; k <= n; ++k) {
    sym_x.push_back(id(n, k));
    sym_y.push_back(id(0, k));
    hole.push_back(id(k, n));
    equator.push_back(id(k, 0));
  }
  set_node_set(mesh, "symmetry_x", sym_x);
  set_node_set(mesh, "symmetry_y", sym_y);
  set_node_set(mesh, "hole_edge", hole);
  set_node_set(mesh, "equator", equator);
  set_node_set(mesh, "load_x", {id(0, 0)});
  set_node_set(mesh, "load_y", {id(n, 0)});
  check_mesh(mesh);
  return mesh;
}

}  // namespace si
