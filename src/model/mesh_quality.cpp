#include "model/mesh_quality.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "model/point_locator.hpp"

namespace si {
namespace {

double angle_deg(const Vector3d& a, const Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / kPi;
}

std::string str(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}

[[noreturn]] void fail_element(const Mesh& mesh, int e, const std::string& what) {
  throw_input(describe_element(mesh, e) + " " + what);
}

void check_sizes_and_nodes(const Mesh& mesh, const MeshQualityLimits& limits) {
  if (mesh.elements.empty()) throw_input("the mesh has no elements");
  if (mesh.directors.size() != mesh.nodes.size()) {
    throw_input("the mesh has " + std::to_string(mesh.nodes.size()) + " nodes but " +
                std::to_string(mesh.directors.size()) + " directors");
  }
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (!mesh.nodes[n].allFinite()) throw_input("node " + std::to_string(n) + " is not finite");
    const double len = mesh.directors[n].norm();
    if (!(std::abs(len - 1) <= limits.director_unit_tolerance)) {
      throw_input("the director of node " + std::to_string(n) + " is not a unit vector (length " +
                  str(len) + ")");
    }
  }
}

void check_connectivity(const Mesh& mesh, int e) {
  const auto& el = mesh.elements[e];
  for (int n : el) {
    if (n < 0 || n >= mesh.num_nodes()) {
      fail_element(mesh, e,
                   "references node " + std::to_string(n) + ", but the mesh has " +
                       std::to_string(mesh.num_nodes()) + " nodes");
    }
  }
  for (int a = 0; a < 4; ++a) {
    for (int b = a + 1; b < 4; ++b) {
      if (el[a] == el[b]) {
        fail_element(mesh, e,
                     "repeats node " + std::to_string(el[a]) +
                         " (a degenerate, triangle-like quadrilateral)");
      }
    }
  }
}

void check_shape(const Mesh& mesh, int e, const MeshQualityLimits& limits) {
  const auto x = element_corners(mesh, e);
  double longest = 0;
  for (int k = 0; k < 4; ++k) longest = std::max(longest, (x[(k + 1) % 4] - x[k]).norm());
  const ElementQuality q = element_quality(mesh, e);
  if (q.area <= 1e-12 * longest * longest) fail_element(mesh, e, "has zero area");
  if (q.min_scaled_jacobian <= 0) {
    fail_element(mesh, e,
                 "is inverted or folded: its node order is clockwise about the directors at a "
                 "corner (scaled Jacobian " +
                     str(q.min_scaled_jacobian) + " <= 0)");
  }
  if (q.max_director_angle_deg > limits.max_director_angle_deg) {
    fail_element(mesh, e,
                 "has a director " + str(q.max_director_angle_deg) +
                     " deg away from its normal (limit " + str(limits.max_director_angle_deg) +
                     " deg)");
  }
  if (q.min_scaled_jacobian < limits.min_scaled_jacobian) {
    fail_element(mesh, e,
                 "is too distorted: scaled Jacobian " + str(q.min_scaled_jacobian) + " < " +
                     str(limits.min_scaled_jacobian));
  }
  if (q.jacobian_ratio < limits.min_jacobian_ratio) {
    fail_element(mesh, e,
                 "is too tapered: Jacobian ratio " + str(q.jacobian_ratio) + " < " +
                     str(limits.min_jacobian_ratio));
  }
  if (q.aspect_ratio > limits.max_aspect_ratio) {
    fail_element(mesh, e,
                 "is too elongated: aspect ratio " + str(q.aspect_ratio) + " > " +
                     str(limits.max_aspect_ratio));
  }
  if (q.warp_deg > limits.max_warp_deg) {
    fail_element(mesh, e,
                 "is too warped: warp angle " + str(q.warp_deg) + " deg > " +
                     str(limits.max_warp_deg) + " deg");
  }
}

void check_unused_nodes(const Mesh& mesh) {
  std::vector<bool> used(mesh.nodes.size(), false);
  for (const auto& el : mesh.elements) {
    for (int n : el) used[n] = true;
  }
  const auto it = std::find(used.begin(), used.end(), false);
  if (it != used.end()) {
    throw_input("node " + std::to_string(it - used.begin()) + " is not used by any element");
  }
}

void check_coincident_nodes(const Mesh& mesh, const MeshQualityLimits& limits) {
  Vector3d lo = mesh.nodes[0], hi = mesh.nodes[0];
  for (const Vector3d& p : mesh.nodes) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double tolerance = limits.coincident_tolerance * std::max((hi - lo).norm(), 1e-300);
  PointLocator locator(tolerance);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const int other = locator.find(mesh.nodes[n]);
    if (other >= 0) {
      throw_input("nodes " + std::to_string(other) + " and " + std::to_string(n) +
                  " coincide (distance " + str((mesh.nodes[n] - mesh.nodes[other]).norm()) +
                  " mm <= " + str(tolerance) + " mm) but are not merged");
    }
    locator.insert(mesh.nodes[n], n);
  }
}

void check_node_sets(const Mesh& mesh) {
  for (const auto& [name, set] : mesh.node_sets) {
    for (size_t k = 0; k < set.size(); ++k) {
      if (set[k] < 0 || set[k] >= mesh.num_nodes()) {
        throw_input("node set '" + name + "' references node " + std::to_string(set[k]) +
                    ", but the mesh has " + std::to_string(mesh.num_nodes()) + " nodes");
      }
      if (k > 0 && set[k] <= set[k - 1]) {
        throw_input("node set '" + name + "' is not sorted and unique");
      }
    }
  }
}

}  // namespace

std::string describe_element(const Mesh& mesh, int e) {
  std::string text = "element " + std::to_string(e) + " (nodes";
  for (int n : mesh.elements[e]) text += " " + std::to_string(n);
  return text + ")";
}

ElementQuality element_quality(const Mesh& mesh, int e) {
  const auto& el = mesh.elements[e];
  const auto x = element_corners(mesh, e);
  const Vector3d normal = element_normal(mesh, e);
  ElementQuality q;
  q.area = element_area(mesh, e);
  q.min_scaled_jacobian = 1;
  double min_jacobian = HUGE_VAL, max_jacobian = -HUGE_VAL;
  double shortest = HUGE_VAL, longest = 0;
  for (int k = 0; k < 4; ++k) {
    const Vector3d to_next = x[(k + 1) % 4] - x[k];
    const Vector3d to_prev = x[(k + 3) % 4] - x[k];
    const Vector3d& d = mesh.directors[el[k]];
    const double scale = to_next.norm() * to_prev.norm();
    const double jacobian = to_next.cross(to_prev).dot(d);
    min_jacobian = std::min(min_jacobian, jacobian);
    max_jacobian = std::max(max_jacobian, jacobian);
    q.min_scaled_jacobian = std::min(q.min_scaled_jacobian, scale > 0 ? jacobian / scale : 0);
    shortest = std::min(shortest, to_next.norm());
    longest = std::max(longest, to_next.norm());
    q.max_director_angle_deg = std::max(q.max_director_angle_deg, angle_deg(d, normal));
  }
  q.jacobian_ratio = max_jacobian > 0 ? min_jacobian / max_jacobian : 0;
  q.aspect_ratio = shortest > 0 ? longest / shortest : HUGE_VAL;
  // Warp: fold angle across each diagonal; a planar quadrilateral has none.
  for (int k = 0; k < 2; ++k) {
    const Vector3d& a = x[k];
    const Vector3d& b = x[k + 1];
    const Vector3d& c = x[k + 2];
    const Vector3d& d = x[(k + 3) % 4];
    q.warp_deg = std::max(q.warp_deg, angle_deg((b - a).cross(c - a), (c - a).cross(d - a)));
  }
  return q;
}

std::optional<std::pair<int, int>> find_inconsistent_orientation(const Mesh& mesh) {
  // Each directed edge may be used once; its reverse by at most one neighbour.
  std::map<std::pair<int, int>, int> owner;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const auto& el = mesh.elements[e];
    for (int k = 0; k < 4; ++k) {
      const auto [it, inserted] = owner.emplace(std::pair{el[k], el[(k + 1) % 4]}, e);
      if (!inserted) return std::pair{it->second, e};
    }
  }
  return std::nullopt;
}

void check_orientation_consistency(const Mesh& mesh) {
  if (const auto pair = find_inconsistent_orientation(mesh)) {
    throw_input(describe_element(mesh, pair->second) + " and " +
                describe_element(mesh, pair->first) +
                " traverse a shared edge in the same direction: inconsistent orientation (or an "
                "edge shared by more than two elements)");
  }
}

void check_element(const Mesh& mesh, int e, const MeshQualityLimits& limits) {
  check_connectivity(mesh, e);
  check_shape(mesh, e, limits);
}

void check_mesh(const Mesh& mesh, const MeshQualityLimits& limits) {
  check_sizes_and_nodes(mesh, limits);
  for (int e = 0; e < mesh.num_elements(); ++e) check_element(mesh, e, limits);
  check_orientation_consistency(mesh);
  check_unused_nodes(mesh);
  if (!limits.allow_coincident_nodes) check_coincident_nodes(mesh, limits);
  check_node_sets(mesh);
}

}  // namespace si
