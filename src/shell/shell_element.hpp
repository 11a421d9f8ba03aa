// The interface shared by all 4-node shell elements (mitc4, mitc4-plain, bernstein4, ...).
//
// Dofs per node, in this order (kShellNodeDofs = 5):
//   0..2  u1, u2, u3   displacement increment in global Cartesian axes (mm)
//   3     a            rotation increment about the node's current v1 (rad)
//   4     b            rotation increment about the node's current v2 (rad)
// so that the director varies as delta d = -a v2 + b v1 (director.hpp). Element vectors hold the
// four nodes one after the other (20 entries). Force is the internal force dW/dq (N, N mm),
// tangent d2W/dq2, both at the current state, with q these increments; a right-handed rotation
// about v1 is positive.
//
// Local frame at an integration point (paper eq 42): n = unit normal of the reference mid-surface,
// oriented to the side of the interpolated director; t1 = projection of material_axis on the
// tangent plane, normalised (if material_axis is within 1e-8 of the normal, t1 = X,xi / |X,xi|
// instead); t2 = n x t1. Laminate angles and the components of R, gamma, N, Q (shell_law.hpp)
// refer to this frame; x3 of the laminate points along n (the director side).
#pragma once

#include <array>
#include <memory>
#include <string>

#include "core/linalg.hpp"
#include "shell/director.hpp"
#include "shell/kinematics.hpp"
#include "shell/shell_law.hpp"

namespace si {

constexpr int kShellNodeDofs = 5;
constexpr int kShellElementDofs = 4 * kShellNodeDofs;

using Vector20d = Eigen::Matrix<double, kShellElementDofs, 1>;
using Matrix20d = Eigen::Matrix<double, kShellElementDofs, kShellElementDofs>;

// Reference geometry. Nodes are numbered counterclockwise seen from the director tip:
// (xi, eta) = (-1,-1), (1,-1), (1,1), (-1,1). D are unit reference directors.
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
  Vector20d force = Vector20d::Zero();
  Matrix20d tangent = Matrix20d::Zero();
  double energy = 0;  // strain energy, N mm
};

// Generalised strains (shell_law.hpp order) at the 4 nodes, extrapolated bilinearly from the
// 2x2 Gauss points (paper P14).
struct ElementStrains {
  std::array<Vector6d, 4> R;
  std::array<Vector2d, 4> gamma;
};

// Linear mode (Kinematics::kLinear): a NodeState is read as the total displacement u and the
// rotation vector theta that takes the reference director D to d (the exact inverse of
// rotate_node applied to reference_node_state(D), |theta| < pi); its components on the REFERENCE
// axes V1, V2 are the rotational dofs. Force = K0 q, energy = 1/2 q^T K0 q, tangent = K0 (the
// nonlinear tangent at the reference state), with q = (u, theta.V1, theta.V2) per node. A linear
// solver should therefore set d with ONE rotate_node(reference_node_state(D), a, b) call per
// solution: (a, b) are then recovered exactly; composing several rotate_node calls changes q at
// second order in the rotations.
class ShellElement {
 public:
  virtual ~ShellElement() = default;
  virtual std::string name() const = 0;
  virtual void compute(const ElementGeometry& geometry, const std::array<NodeState, 4>& nodes,
                       const ShellLaw& law, Kinematics kinematics, const ElementRequest& request,
                       ElementResponse& response) const = 0;
  virtual ElementStrains strains_at_nodes(const ElementGeometry& geometry,
                                          const std::array<NodeState, 4>& nodes,
                                          Kinematics kinematics) const = 0;
};

// The elements: mitc4 (default choice of the toolkit: MITC4 shear + EAS-4 membrane),
// mitc4-plain (MITC4 with the plain bilinear membrane, stiff in in-plane bending; kept for
// comparison) and bernstein4 (the source paper's element, kept to reproduce and measure it).
// Their names ("mitc4", "mitc4-plain", "bernstein4") are ShellElement::name().
enum class ElementType { kMitc4, kMitc4Plain, kBernstein4 };

std::unique_ptr<ShellElement> make_shell_element(ElementType type);

}  // namespace si
