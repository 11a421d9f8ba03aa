#include "model/spherical_cap_mesh.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "model/mesh_quality.hpp"

namespace si {

double cap_height(const SphericalCapMeshSpec& spec) {
  const double r = spec.sphere_radius, c = spec.base_radius;
  return r - std::sqrt(r * r - c * c);
}

void validate(const SphericalCapMeshSpec& spec) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  if (!positive(spec.sphere_radius)) {
    throw_input("the sphere radius must be positive",
                {"", "sphere_radius", std::to_string(spec.sphere_radius)});
  }
  if (!positive(spec.base_radius) || spec.base_radius >= spec.sphere_radius) {
    throw_input("the base radius must be positive and smaller than the sphere radius",
                {"", "base_radius", std::to_string(spec.base_radius)});
  }
  if (!positive(spec.size_apex) || spec.size_apex > spec.base_radius) {
    throw_input("must be positive and at most the base radius",
                {"", "size_apex", std::to_string(spec.size_apex)});
  }
  if (!positive(spec.size_edge) || spec.size_edge > spec.base_radius) {
    throw_input("must be positive and at most the base radius",
                {"", "size_edge", std::to_string(spec.size_edge)});
  }
  if (spec.size_apex > spec.size_edge) {
    throw_input("must not exceed size_edge: the mesh refines towards the apex",
                {"", "size_apex", std::to_string(spec.size_apex)});
  }
  if (!(std::isfinite(spec.refine_radius) && spec.refine_radius >= 0)) {
    throw_input("must be zero or positive",
                {"", "refine_radius", std::to_string(spec.refine_radius)});
  }
}

Mesh spherical_cap_mesh(const SphericalCapMeshSpec& spec) {
  validate(spec);
  const double r = spec.sphere_radius;
  const double arc = r * std::asin(spec.base_radius / r);  // apex-to-edge geodesic length
  Mesh mesh = disk_o_grid({arc, spec.size_apex, spec.size_edge, spec.refine_radius}, spec.symmetry);

  const Vector3d centre(0, 0, cap_height(spec) - r);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    Vector3d& p = mesh.nodes[n];
    const double s = std::hypot(p.x(), p.y());
    const double phi = s / r;  // polar angle from the apex
    const double scale = s > 0 ? r * std::sin(phi) / s : 0;
    p = Vector3d(scale * p.x(), scale * p.y(), centre.z() + r * std::cos(phi));
    mesh.directors[n] = (p - centre).normalized();
  }
  // Only the rim of the flat grid maps to z = 0 (round-off); the next ring is far above it.
  const double tol = 1e-9 * spec.base_radius;
  set_node_set(mesh, "edge",
               nodes_where(mesh, [&](const Vector3d& p) { return std::abs(p.z()) < tol; }));
  set_node_set(mesh, "apex",
               nodes_where(mesh, [](const Vector3d& p) { return p.x() == 0 && p.y() == 0; }));
  add_symmetry_node_sets(mesh, spec.symmetry);
  check_mesh(mesh);
  return mesh;
}

}  // namespace si
