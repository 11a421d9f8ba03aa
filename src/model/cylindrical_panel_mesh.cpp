#include "model/cylindrical_panel_mesh.hpp"

#include <cmath>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "model/mesh_quality.hpp"
#include "model/structured_grid.hpp"

namespace si {
namespace {}  // namespace

Mesh cylindrical_panel_mesh(double radius, double length, double half_angle_deg, int n_axial,
                            int n_circ, PanelPart part) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!positive(radius)) throw_input("must be positive", {"", "radius", std::to_string(radius)});
  if (!positive(length)) throw_input("must be positive", {"", "length", std::to_string(length)});
  if (!positive(half_angle_deg) || half_angle_deg > 180) {
    throw_input("must be in (0, 180] deg", {"", "half_angle_deg", std::to_string(half_angle_deg)});
  }
  const bool full = part == PanelPart::kFull;
  const int step = full ? 2 : 1;
  if (n_axial < step || n_axial % step != 0) {
    throw_input(full ? "must be even and positive for the full panel" : "must be positive",
                {"", "n_axial", std::to_string(n_axial)});
  }
  if (n_circ < step || n_circ % step != 0) {
    throw_input(full ? "must be even and positive for the full panel" : "must be positive",
                {"", "n_circ", std::to_string(n_circ)});
  }

  const double half_angle = half_angle_deg * kPi / 180;
  const int i_crown = full ? n_circ / 2 : 0, j_mid = full ? n_axial / 2 : 0;
  // Offsets from the mid-lines in integers, so that the mid-lines are exactly theta = 0, y = 0.
  std::vector<double> thetas, ys;
  for (int i = 0; i <= n_circ; ++i)
    thetas.push_back(half_angle * (i - i_crown) / static_cast<double>(n_circ - i_crown));
  for (int j = 0; j <= n_axial; ++j)
    ys.push_back(length / 2 * (j - j_mid) / static_cast<double>(n_axial - j_mid));
  return cylindrical_panel_mesh(radius, thetas, ys, part);
}

Mesh cylindrical_panel_mesh(double radius, const std::vector<double>& thetas,
                            const std::vector<double>& ys, PanelPart part) {
  const bool full = part == PanelPart::kFull;
  const auto valid = [full](const std::vector<double>& s) {
    bool ok = s.size() >= 2 && (full ? s.size() % 2 == 1 : s.front() == 0);
    for (std::size_t k = 1; k < s.size() && ok; ++k) ok = s[k] > s[k - 1];
    return ok && (!full || s[s.size() / 2] == 0);
  };
  if (!valid(thetas) || !valid(ys))
    throw_input(full ? "panel stations must increase, be odd in number and have 0 in the middle"
                     : "panel stations must increase from 0");
  const int n_circ = static_cast<int>(thetas.size()) - 1;
  const int n_axial = static_cast<int>(ys.size()) - 1;
  const int i_crown = full ? n_circ / 2 : 0, j_mid = full ? n_axial / 2 : 0;
  // u = theta, v = y: x_theta cross x_y = R (sin theta, 0, cos theta), outward.
  Mesh mesh = structured_grid(n_circ, n_axial, [&](int i, int j) {
    const double t = thetas[i];
    return Vector3d(radius * std::sin(t), ys[j], radius * std::cos(t));
  });
  for (int j = 0; j <= n_axial; ++j) {
    for (int i = 0; i <= n_circ; ++i) {
      const double t = thetas[i];
      mesh.directors.push_back(Vector3d(std::sin(t), 0, std::cos(t)));
    }
  }
  const auto id = [n_circ](int i, int j) { return i + (n_circ + 1) * j; };
  std::vector<int> ends, edges, midplane, crown;
  for (int i = 0; i <= n_circ; ++i) {
    ends.push_back(id(i, n_axial));
    if (full) ends.push_back(id(i, 0));
    midplane.push_back(id(i, j_mid));
  }
  for (int j = 0; j <= n_axial; ++j) {
    edges.push_back(id(n_circ, j));
    if (full) edges.push_back(id(0, j));
    crown.push_back(id(i_crown, j));
  }
  set_node_set(mesh, "curved_ends", ends);
  set_node_set(mesh, "straight_edges", edges);
  set_node_set(mesh, "axial_midplane", midplane);
  set_node_set(mesh, "crown", crown);
  set_node_set(mesh, "center", {id(i_crown, j_mid)});
  set_node_set(mesh, "free_edge_mid", {id(n_circ, j_mid)});
  check_mesh(mesh);
  return mesh;
}

Mesh pinched_cylinder_octant_mesh(double radius, double length, int n_axial, int n_circ) {
  Mesh mesh = cylindrical_panel_mesh(radius, length, 90, n_axial, n_circ, PanelPart::kQuarter);
  mesh.node_sets["diaphragm"] = mesh.node_sets.at("curved_ends");
  mesh.node_sets["symmetry_x"] = mesh.node_sets.at("crown");
  mesh.node_sets["symmetry_y"] = mesh.node_sets.at("axial_midplane");
  mesh.node_sets["symmetry_z"] = mesh.node_sets.at("straight_edges");
  mesh.node_sets["load"] = mesh.node_sets.at("center");
  // sin(pi/2) is exact but cos(pi/2) is not: put the side exactly on the symmetry plane z = 0.
  for (int n : mesh.node_sets.at("symmetry_z")) {
    mesh.nodes[n].z() = 0;
    mesh.directors[n] = Vector3d::UnitX();
  }
  return mesh;
}

}  // namespace si
