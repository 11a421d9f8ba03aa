#pragma once

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/linalg.hpp"
#include "shell/director.hpp"
#include "shell/kinematics.hpp"
#include "shell/shell_law.hpp"

namespace si {

constexpr int kShellNodeDofs =
    5;  // per node: u1 u2 u3 (global axes), rotation about v1, rotation about v2
struct ElementGeometry {
  std::array<Vector3d, 4> X;
  std::array<Vector3d, 4> D;
  Vector3d material_axis{1, 0, 0};
};
struct ElementRequest {
  bool force = true;
  bool tangent = true;
};
struct ElementResponse {
  Eigen::Matrix<double, 20, 1> force;
  Eigen::Matrix<double, 20, 20> tangent;
  double energy = 0;
};
// force = dW/dq (internal force), tangent = d2W/dq2; q = increments (du, rotations about current
// v1, v2), node-major
struct ElementStrains {
  std::array<Vector6d, 4> R;
  std::array<Vector2d, 4> gamma;
};  // at the 4 nodes
class ShellElement {
 public:
  virtual ~ShellElement() = default;
  virtual std::string name() const = 0;
  virtual void compute(const ElementGeometry&, const std::array<NodeState, 4>&, const ShellLaw&,
                       Kinematics, const ElementRequest&, ElementResponse&) const = 0;
  virtual ElementStrains strains_at_nodes(const ElementGeometry&, const std::array<NodeState, 4>&,
                                          Kinematics) const = 0;
};
std::unique_ptr<ShellElement> make_shell_element(
    const std::string& name);  // "mitc4" | "bernstein4"
// In linear mode (Kinematics::kLinear) the element's force is K q with q the total displacement and
// small rotations from the reference state; the static driver then solves K q = f once.

}  // namespace si
