#include "model/supports.hpp"

#include <cmath>

#include "core/error.hpp"
#include "model/node_set.hpp"
#include "shell/director.hpp"

namespace si {
namespace {

constexpr double kAlignTolerance = 1e-8;

std::string node_text(int node, const Vector3d& D) {
  return "node " + std::to_string(node) + " (director " + std::to_string(D.x()) + ", " +
         std::to_string(D.y()) + ", " + std::to_string(D.z()) + ")";
}

// Global axis k with |D.e_k| within the tolerance of 1, or -1.
int aligned_axis(const Vector3d& D) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(D[k]) - 1.0) < kAlignTolerance) return k;
  return -1;
}

void add_zero(std::vector<PrescribedDof>& out, int node, int local) {
  out.push_back({DofMap::dof(node, local), 0.0});
}

// The rotation dof (3 or 4) to fix so that the director stays in the plane with normal e_k.
int symmetry_rotation_dof(int node, const Vector3d& D, int k, const std::string& who) {
  if (std::abs(D[k]) > kAlignTolerance)
    throw_input(who + ": the director of " + node_text(node, D) +
                " is not in the symmetry plane (normal axis " + std::to_string(k) +
                "): a symmetric shell has its directors in the plane");
  const NodeState frame = reference_node_state(D);
  // Motion of d for a unit rotation about v1 and v2, as component along the plane normal.
  const double c1 = frame.v1.cross(D)[k];
  const double c2 = frame.v2.cross(D)[k];
  const auto clean = [](double c) {
    return std::abs(c) < kAlignTolerance || std::abs(std::abs(c) - 1.0) < kAlignTolerance;
  };
  if (!clean(c1) || !clean(c2))
    throw_input(who + ": the nodal frame of " + node_text(node, D) +
                " is not aligned with the symmetry plane (normal axis " + std::to_string(k) +
                "): neither rotation axis v1 = (e2 x D)/|e2 x D| nor v2 = D x v1 is along the "
                "plane normal, so the in-plane director condition is not a single dof");
  return std::abs(c1) > std::abs(c2) ? 3 : 4;
}

void add_support(const Mesh& mesh, const Support& s, const std::string& who,
                 std::vector<PrescribedDof>& out) {
  const std::vector<int>& nodes = find_node_set(mesh, s.node_set, who);
  for (int node : nodes) {
    const Vector3d& D = mesh.directors[node];
    switch (s.kind) {
      case SupportKind::kClamped:
        for (int i = 0; i < kShellNodeDofs; ++i) add_zero(out, node, i);
        break;
      case SupportKind::kHinged:
        for (int i = 0; i < 3; ++i) add_zero(out, node, i);
        break;
      case SupportKind::kSimplySupported: {
        const int k = aligned_axis(D);
        if (k < 0)
          throw_input(who +
                          ": simply supported means u.D = 0, a single dof only where the "
                          "director is a global axis; the director of " +
                          node_text(node, D) +
                          " is not within 1e-8 of a global axis (use a hinged support or fixed "
                          "dofs instead)",
                      Where{"", "node_set", s.node_set, 0});
        add_zero(out, node, k);
        break;
      }
      case SupportKind::kSymmetryPlane:
        if (s.plane_axis < 0 || s.plane_axis > 2)
          throw_input(who + ": symmetry plane axis must be 0, 1 or 2 (normal e_x, e_y, e_z), got " +
                      std::to_string(s.plane_axis));
        add_zero(out, node, s.plane_axis);
        add_zero(out, node, symmetry_rotation_dof(node, D, s.plane_axis, who));
        break;
      case SupportKind::kFixedDofs:
        if (s.local_dofs.empty()) throw_input(who + ": fixed-dof support lists no dofs");
        for (int i : s.local_dofs) {
          if (i < 0 || i >= kShellNodeDofs)
            throw_input(who + ": fixed dof " + std::to_string(i) +
                        " is not in 0..4 (u1 u2 u3, "
                        "rotation about v1, rotation about v2)");
          add_zero(out, node, i);
        }
        break;
    }
  }
}

}  // namespace

std::vector<PrescribedDof> prescribed_dofs(
    const Mesh& mesh, const std::vector<Support>& supports,
    const std::vector<PrescribedDisplacement>& displacements) {
  SI_REQUIRE(static_cast<int>(mesh.directors.size()) == mesh.num_nodes(),
             "mesh has " + std::to_string(mesh.directors.size()) + " directors for " +
                 std::to_string(mesh.num_nodes()) + " nodes");
  std::vector<PrescribedDof> out;
  for (std::size_t i = 0; i < supports.size(); ++i)
    add_support(mesh, supports[i], "support " + std::to_string(i), out);
  for (std::size_t i = 0; i < displacements.size(); ++i) {
    const PrescribedDisplacement& p = displacements[i];
    const std::string who = "prescribed displacement " + std::to_string(i);
    if (p.component < 0 || p.component > 2)
      throw_input(who + ": component must be 0, 1 or 2 (global x, y, z), got " +
                  std::to_string(p.component));
    if (!std::isfinite(p.value)) throw_input(who + ": value is not finite");
    for (int node : find_node_set(mesh, p.node_set, who))
      out.push_back({DofMap::dof(node, p.component), p.value});
  }
  return out;
}

DofMap make_dof_map(const Mesh& mesh, const std::vector<Support>& supports,
                    const std::vector<PrescribedDisplacement>& displacements) {
  return DofMap(mesh.num_nodes(), prescribed_dofs(mesh, supports, displacements));
}

}  // namespace si
