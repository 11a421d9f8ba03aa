#include "model/named_supports.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "model/mesh_topology.hpp"
#include "model/node_set.hpp"

namespace si {
namespace {

double bounding_diagonal(const Mesh& mesh) {
  Vector3d lo = mesh.nodes.front(), hi = mesh.nodes.front();
  for (const Vector3d& p : mesh.nodes) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return std::max((hi - lo).norm(), 1e-300);
}

const std::vector<int>& nodes_of(const Mesh& mesh, const NamedSupportSpec& spec) {
  try {
    return find_node_set(mesh, spec.on, "support");
  } catch (const Error& e) {
    throw Error(e.kind(), e.reason(), spec.where);
  }
}

// The plane normal of a symmetry set: the one axis along which all its nodes agree.
int symmetry_axis(const Mesh& mesh, const NamedSupportSpec& spec) {
  if (spec.symmetry_axis >= 0) return spec.symmetry_axis;
  const std::vector<int>& nodes = nodes_of(mesh, spec);
  const double tol = 1e-9 * bounding_diagonal(mesh);
  int axis = -1, flat_axes = 0;
  for (int k = 0; k < 3; ++k) {
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int n : nodes) {
      lo = std::min(lo, mesh.nodes[n][k]);
      hi = std::max(hi, mesh.nodes[n][k]);
    }
    if (hi - lo <= tol) {
      axis = k;
      ++flat_axes;
    }
  }
  if (flat_axes != 1)
    throw_input("cannot tell the symmetry plane of '" + spec.on +
                    "' from its nodes (they must share exactly one of x, y, z); give it with "
                    "`normal: x`, `y` or `z`",
                spec.where);
  return axis;
}

void add_named(const Mesh& mesh, const NamedSupportSpec& spec, SupportPlan& plan) {
  switch (spec.type) {
    case SupportType::kClamped:
      plan.supports.push_back({SupportKind::kClamped, spec.on, -1, {}});
      return;
    case SupportType::kHinged:
      plan.supports.push_back({SupportKind::kHinged, spec.on, -1, {}});
      return;
    case SupportType::kSimplySupported:
      plan.supports.push_back({SupportKind::kSimplySupported, spec.on, -1, {}});
      return;
    case SupportType::kSymmetry:
      plan.supports.push_back(
          {SupportKind::kSymmetryPlane, spec.on, symmetry_axis(mesh, spec), {}});
      return;
    case SupportType::kDisplacement: {
      Support fixed{SupportKind::kFixedDofs, spec.on, -1, {}};
      for (const auto& [dof, value] : spec.values) {
        const int local = static_cast<int>(dof);  // u_x u_y u_z theta_1 theta_2 = dofs 0..4
        if (value == 0.0)
          fixed.local_dofs.push_back(local);
        else if (local < 3)
          plan.displacements.push_back({spec.on, local, value});
        else
          throw_input(
              "a prescribed rotation must be 0 (the rotation dofs are increments about "
              "the node's axes; only holding them is supported)",
              spec.where);
      }
      if (!fixed.local_dofs.empty()) plan.supports.push_back(fixed);
      return;
    }
    case SupportType::kFree:
      return;
  }
}

bool in_set(const std::vector<int>& sorted, int node) {
  return std::binary_search(sorted.begin(), sorted.end(), node);
}

Support support_of(SupportType type, const std::string& set) {
  switch (type) {
    case SupportType::kHinged:
      return {SupportKind::kHinged, set, -1, {}};
    case SupportType::kSimplySupported:
      return {SupportKind::kSimplySupported, set, -1, {}};
    default:
      return {SupportKind::kClamped, set, -1, {}};
  }
}

}  // namespace

SupportPlan plan_supports(Mesh& mesh, const std::vector<NamedSupportSpec>& named,
                          SupportType default_type, const std::vector<std::string>& covered_sets) {
  SupportPlan plan;
  std::vector<std::vector<int>> covering;
  for (const NamedSupportSpec& spec : named) {
    covering.push_back(nodes_of(mesh, spec));
    const std::size_t supports_before = plan.supports.size();
    add_named(mesh, spec, plan);
    // Check the entry against the mesh now, so that a misfit names the case-file entry.
    try {
      prescribed_dofs(
          mesh, std::vector<Support>(plan.supports.begin() + supports_before, plan.supports.end()),
          {});
    } catch (const Error& e) {
      throw Error(e.kind(), e.reason(), spec.where);
    }
  }
  for (const std::string& name : covered_sets)
    covering.push_back(find_node_set(mesh, name, "support"));
  if (default_type == SupportType::kFree || default_type == SupportType::kSymmetry ||
      default_type == SupportType::kDisplacement)
    return plan;
  std::vector<int> nodes;
  for (const auto& [a, b] : boundary_segments(mesh)) {
    const bool covered = std::any_of(covering.begin(), covering.end(), [&](const auto& set) {
      return in_set(set, a) && in_set(set, b);
    });
    if (covered) continue;
    nodes.push_back(a);
    nodes.push_back(b);
  }
  if (nodes.empty()) return plan;
  set_node_set(mesh, "default_edge", nodes);
  plan.supports.push_back(support_of(default_type, "default_edge"));
  return plan;
}

void hold_inplane_rigid_body(const Mesh& mesh, const std::string& centre,
                             const std::string& far_node, SupportPlan& plan) {
  for (const Vector3d& d : mesh.directors)
    if (std::abs(std::abs(d.z()) - 1.0) > 1e-12) return;
  // Rigid in-plane motion u = (a - c y, b + c x): a held u_x at (x, y) is the row (1, 0, -y),
  // a held u_y the row (0, 1, x); coordinates relative to the centre, scaled by the mesh size.
  const int c = find_node_set(mesh, centre, "support").front();
  const int f = find_node_set(mesh, far_node, "support").front();
  const double scale = bounding_diagonal(mesh);
  const auto row = [&](int node, int local) {
    const Vector3d p = (mesh.nodes[node] - mesh.nodes[c]) / scale;
    return local == 0 ? Vector3d(1, 0, -p.y()) : Vector3d(0, 1, p.x());
  };
  Matrix3d normal = Matrix3d::Zero();
  for (const PrescribedDof& p : prescribed_dofs(mesh, plan.supports, plan.displacements)) {
    const int local = p.dof % kShellNodeDofs;
    if (local > 1) continue;
    const Vector3d r = row(p.dof / kShellNodeDofs, local);
    normal += r * r.transpose();
  }
  const auto rank = [](const Matrix3d& m) {
    const Vector3d ev = Eigen::SelfAdjointEigenSolver<Matrix3d>(m).eigenvalues();
    const double top = std::max(ev.maxCoeff(), 1.0);
    return static_cast<int>((ev.array() > 1e-10 * top).count());
  };
  const std::pair<int, int> candidates[] = {{c, 0}, {c, 1}, {f, 1}};
  const std::string names[] = {centre, centre, far_node};
  for (int k = 0; k < 3; ++k) {
    const Vector3d r = row(candidates[k].first, candidates[k].second);
    const Matrix3d with = normal + r * r.transpose();
    if (rank(with) <= rank(normal)) continue;
    normal = with;
    plan.supports.push_back({SupportKind::kFixedDofs, names[k], -1, {candidates[k].second}});
  }
}

}  // namespace si
