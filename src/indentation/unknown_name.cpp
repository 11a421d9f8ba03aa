// IndentationProblem::unknown_name: what an unknown of z = (x, mu, lambda, alpha) is, for the
// report of a corrector that stalled with its residual on one unknown (docs/performance.md: the
// 1e6-unknown cap's steps past 9.68 mm).
#include <array>
#include <cstdio>
#include <string>

#include "indentation/indentation_problem.hpp"

namespace si {
namespace {

// The node-major local dofs of dof_map.hpp.
constexpr std::array<const char*, kShellNodeDofs> kComponents = {
    "u1", "u2", "u3", "rotation about v1", "rotation about v2"};

std::string node_at(const Mesh& mesh, int node) {
  const Vector3d& x = mesh.nodes[node];
  char buf[96];
  std::snprintf(buf, sizeof buf, "node %d at (%.4g, %.4g, %.4g) mm", node, x.x(), x.y(), x.z());
  return buf;
}

}  // namespace

std::string IndentationProblem::unknown_name(int i) const {
  const UnknownLayout l = layout();
  if (i < 0 || i >= l.size()) return {};
  const Mesh& mesh = model().mesh;
  if (i < l.shell) {
    const int dof = dofs().free_dofs()[i];
    return node_at(mesh, dof / kShellNodeDofs) + ", " + kComponents[dof % kShellNodeDofs];
  }
  if (i < l.lambda_begin()) return "support frame row " + std::to_string(i - l.frame_begin());
  if (i < l.alpha_index()) {
    const int row = i - l.lambda_begin();
    return "the contact row of " + node_at(mesh, candidates()[row]);
  }
  return "the local contact law's approach";
}

}  // namespace si
