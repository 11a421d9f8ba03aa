#include "model/plate_meshes.hpp"

#include <cmath>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "model/mesh_quality.hpp"
#include "model/structured_grid.hpp"

namespace si {
namespace {

void require_positive(double value, const char* key) {
  if (!(std::isfinite(value) && value > 0)) {
    throw_input("must be positive", {"", key, std::to_string(value)});
  }
}

void require_divisions(int n, int at_least, const char* key) {
  if (n < at_least) {
    throw_input("needs at least " + std::to_string(at_least) + " elements",
                {"", key, std::to_string(n)});
  }
}

void require_stations(const std::vector<double>& s, const char* key) {
  bool increasing = s.size() >= 2;
  for (std::size_t k = 1; k < s.size() && increasing; ++k) increasing = s[k] > s[k - 1];
  if (!increasing) throw_input("needs at least 2 strictly increasing stations", {"", key, ""});
}

}  // namespace

Mesh rectangular_plate_mesh(double lx, double ly, int nx, int ny) {
  require_positive(lx, "lx");
  require_positive(ly, "ly");
  require_divisions(nx, 1, "nx");
  require_divisions(ny, 1, "ny");
  std::vector<double> xs, ys;
  for (int i = 0; i <= nx; ++i) xs.push_back(lx * i / nx);
  for (int j = 0; j <= ny; ++j) ys.push_back(ly * j / ny);
  return rectangular_plate_mesh(xs, ys);
}

Mesh rectangular_plate_mesh(const std::vector<double>& xs, const std::vector<double>& ys) {
  require_stations(xs, "xs");
  require_stations(ys, "ys");
  const int nx = static_cast<int>(xs.size()) - 1, ny = static_cast<int>(ys.size()) - 1;
  Mesh mesh = structured_grid(nx, ny, [&](int i, int j) { return Vector3d(xs[i], ys[j], 0); });
  mesh.directors.assign(mesh.nodes.size(), Vector3d::UnitZ());
  const auto id = [nx](int i, int j) { return i + (nx + 1) * j; };
  std::vector<int> x0, x1, y0, y1;
  for (int j = 0; j <= ny; ++j) {
    x0.push_back(id(0, j));
    x1.push_back(id(nx, j));
  }
  for (int i = 0; i <= nx; ++i) {
    y0.push_back(id(i, 0));
    y1.push_back(id(i, ny));
  }
  std::vector<int> edge = x0;
  for (const auto* side : {&x1, &y0, &y1}) edge.insert(edge.end(), side->begin(), side->end());
  set_node_set(mesh, "edge_x0", x0);
  set_node_set(mesh, "edge_x1", x1);
  set_node_set(mesh, "edge_y0", y0);
  set_node_set(mesh, "edge_y1", y1);
  set_node_set(mesh, "edge", edge);
  if (nx % 2 == 0 && ny % 2 == 0) set_node_set(mesh, "center", {id(nx / 2, ny / 2)});
  check_mesh(mesh);
  return mesh;
}

Mesh circular_plate_mesh(double radius, double size_center, double size_edge, double refine_radius,
                         Symmetry symmetry) {
  Mesh mesh = disk_o_grid({radius, size_center, size_edge, refine_radius}, symmetry);
  const double tol = 1e-9 * radius;
  set_node_set(mesh, "edge", nodes_where(mesh, [&](const Vector3d& p) {
                 return std::abs(p.norm() - radius) < tol;
               }));
  set_node_set(mesh, "center", nodes_where(mesh, [](const Vector3d& p) { return p.isZero(0); }));
  add_symmetry_node_sets(mesh, symmetry);
  check_mesh(mesh);
  return mesh;
}

Mesh macneal_harder_patch_mesh() {
  Mesh mesh;
  mesh.nodes = {{0, 0, 0},       {0.24, 0, 0},    {0.24, 0.12, 0}, {0, 0.12, 0},
                {0.04, 0.02, 0}, {0.18, 0.03, 0}, {0.16, 0.08, 0}, {0.08, 0.08, 0}};
  mesh.directors.assign(mesh.nodes.size(), Vector3d::UnitZ());
  mesh.elements = {{4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  set_node_set(mesh, "boundary", {0, 1, 2, 3});
  set_node_set(mesh, "interior", {4, 5, 6, 7});
  check_mesh(mesh);
  return mesh;
}

Mesh annulus_with_slit_mesh(double inner_r, double outer_r, int n_radial, int n_circ) {
  require_positive(inner_r, "inner_r");
  if (!(std::isfinite(outer_r) && outer_r > inner_r)) {
    throw_input("the outer radius must exceed the inner radius",
                {"", "outer_r", std::to_string(outer_r)});
  }
  require_divisions(n_radial, 1, "n_radial");
  require_divisions(n_circ, 3, "n_circ");
  // u radial, v counter-clockwise: x_r cross x_theta = +z. Angle 2 pi is a separate node row.
  Mesh mesh = structured_grid(n_radial, n_circ, [&](int i, int j) {
    const double r = inner_r + (outer_r - inner_r) * i / n_radial;
    if (j == n_circ) return Vector3d(r, 0, 0);  // exactly on the slit, like j = 0
    const double angle = 2 * kPi * j / n_circ;
    return Vector3d(r * std::cos(angle), r * std::sin(angle), 0);
  });
  mesh.directors.assign(mesh.nodes.size(), Vector3d::UnitZ());
  const auto id = [n_radial](int i, int j) { return i + (n_radial + 1) * j; };
  std::vector<int> fixed, loaded, inner, outer;
  for (int i = 0; i <= n_radial; ++i) {
    fixed.push_back(id(i, 0));
    loaded.push_back(id(i, n_circ));
  }
  for (int j = 0; j <= n_circ; ++j) {
    inner.push_back(id(0, j));
    outer.push_back(id(n_radial, j));
  }
  set_node_set(mesh, "slit_fixed", fixed);
  set_node_set(mesh, "slit_loaded", loaded);
  set_node_set(mesh, "inner_edge", inner);
  set_node_set(mesh, "outer_edge", outer);
  set_node_set(mesh, "loaded_inner", {id(0, n_circ)});
  set_node_set(mesh, "loaded_outer", {id(n_radial, n_circ)});
  MeshQualityLimits limits;
  limits.allow_coincident_nodes = true;
  check_mesh(mesh, limits);
  return mesh;
}

}  // namespace si
