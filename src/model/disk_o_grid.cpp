#include "model/disk_o_grid.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "model/graded_stations.hpp"
#include "model/structured_grid.hpp"

namespace si {
namespace {

// Radial elements are kept at most this many times longer than their tangential size.
constexpr double kMaxRadialStretch = 4;

// Target radial element size at distance s from the centre, with n tangential divisions per
// 45-degree sector.
double target_size(const DiskGrading& g, int n, double s) {
  double size = g.size_center;
  if (s > g.refine_radius && g.refine_radius < g.radius) {
    const double t = (s - g.refine_radius) / (g.radius - g.refine_radius);
    size += t * (g.size_edge - g.size_center);
  }
  return std::min(size, kMaxRadialStretch * kPi * s / (4 * n));
}

// Points of a radial line from `inner` (on the square) to `outer` (on the circle), at the
// fractions of the graded stations.
Vector3d on_line(const Vector3d& inner, const Vector3d& outer, double fraction) {
  return inner + fraction * (outer - inner);
}

Mesh quarter_disk(const DiskGrading& g) {
  const double r_refine = std::min(g.refine_radius, g.radius);
  // Tangential divisions per 45-degree sector: the arc length pi r / 4 over n is the size.
  const int n =
      std::max({1, static_cast<int>(std::ceil(kPi * r_refine / (4 * g.size_center) - 1e-9)),
                static_cast<int>(std::ceil(kPi * g.radius / (4 * g.size_edge) - 1e-9))});
  const double a = std::min(n * g.size_center, 0.5 * g.radius);
  const auto stations =
      graded_stations(a, g.radius, [&](double s) { return target_size(g, n, s); });
  const int m = static_cast<int>(stations.size()) - 1;
  const auto fraction = [&](int k) { return (stations[k] - a) / (g.radius - a); };
  const auto rim = [&](double angle) {
    return Vector3d(g.radius * std::cos(angle), g.radius * std::sin(angle), 0);
  };

  Mesh quarter =
      structured_grid(n, n, [&](int i, int j) { return Vector3d(a * i / n, a * j / n, 0); });
  // Sector 0..45 deg: from the side x = a; u radial, v counter-clockwise.
  merge_into(quarter,
             structured_grid(m, n,
                             [&](int k, int i) {
                               return on_line(Vector3d(a, a * i / n, 0), rim(kPi / 4 * i / n),
                                              fraction(k));
                             }),
             1e-9 * g.radius);
  // Sector 45..90 deg: from the side y = a.
  merge_into(quarter,
             structured_grid(m, n,
                             [&](int k, int i) {
                               return on_line(Vector3d(a * (n - i) / n, a, 0),
                                              rim(kPi / 4 * (1 + static_cast<double>(i) / n)),
                                              fraction(k));
                             }),
             1e-9 * g.radius);
  return quarter;
}

}  // namespace

void validate(const DiskGrading& g) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!positive(g.radius))
    throw_input("the disk radius must be positive", {"", "radius", std::to_string(g.radius)});
  if (!positive(g.size_center) || g.size_center > g.radius) {
    throw_input("the centre element size must be positive and at most the radius",
                {"", "size_center", std::to_string(g.size_center)});
  }
  if (!positive(g.size_edge) || g.size_edge > g.radius) {
    throw_input("the edge element size must be positive and at most the radius",
                {"", "size_edge", std::to_string(g.size_edge)});
  }
  if (g.size_center > g.size_edge) {
    throw_input(
        "the O-grid refines towards the centre: the centre size must not exceed the "
        "edge size (" +
            std::to_string(g.size_edge) + ")",
        {"", "size_center", std::to_string(g.size_center)});
  }
  if (!(std::isfinite(g.refine_radius) && g.refine_radius >= 0)) {
    throw_input("the refinement radius must be zero or positive",
                {"", "refine_radius", std::to_string(g.refine_radius)});
  }
}

Mesh disk_o_grid(const DiskGrading& grading, Symmetry symmetry) {
  validate(grading);
  const Mesh quarter = quarter_disk(grading);
  Mesh disk = quarter;
  if (symmetry == Symmetry::kFull) {
    for (int turn = 1; turn < 4; ++turn) {
      const double angle = kPi / 2 * turn;
      Mesh rotated = quarter;
      for (Vector3d& p : rotated.nodes) {
        p = Vector3d(std::cos(angle) * p.x() - std::sin(angle) * p.y(),
                     std::sin(angle) * p.x() + std::cos(angle) * p.y(), 0);
      }
      merge_into(disk, rotated, 1e-9 * grading.radius);
    }
  }
  // Round-off of the rotations and of cos(pi/2) must not move nodes off the symmetry axes.
  for (Vector3d& p : disk.nodes) {
    if (std::abs(p.x()) < 1e-12 * grading.radius) p.x() = 0;
    if (std::abs(p.y()) < 1e-12 * grading.radius) p.y() = 0;
  }
  disk.directors.assign(disk.nodes.size(), Vector3d::UnitZ());
  return disk;
}

void add_symmetry_node_sets(Mesh& mesh, Symmetry symmetry) {
  if (symmetry != Symmetry::kQuarter) return;
  set_node_set(mesh, "symmetry_x", nodes_where(mesh, [](const Vector3d& p) { return p.x() == 0; }));
  set_node_set(mesh, "symmetry_y", nodes_where(mesh, [](const Vector3d& p) { return p.y() == 0; }));
}

}  // namespace si
