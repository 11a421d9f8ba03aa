// The 4-node degenerated (Ahmad-type) Reissner-Mindlin shell element (paper eqs 35-54), written
// once and parametrised by its shape-function set, its transverse-shear treatment and its Gauss
// rule:
//   mitc4      = bilinear shapes, MITC4 tying (Dvorkin & Bathe 1984), EAS-4 membrane (Simo &
//                Rifai 1990; Buechter, Ramm & Roehl 1994), 2x2 Gauss (the default)
//   mitc4-plain = the same with the plain bilinear membrane strains (locks in in-plane bending)
//   bernstein4 = the paper's Bernstein shapes (eqs 68-71), plain shear, 4x4 Gauss (the paper
//                does not state its rule; 4x4 integrates the products of its cubic shapes
//                exactly on a parallelogram)
//
// Kinematics (Simo & Fox 1989): position x = sum N_I (X_I + u_I), director d = sum N_I d_I
// (interpolated, not normalised). Covariant strain measures in (xi, eta), a,b in {1,2}:
//   eps_ab   = 1/2 (x,a . x,b - X,a . X,b)
//   kappa_ab = 1/2 (x,a . d,b + x,b . d,a - X,a . D,b - X,b . D,a)
//   gamma_a  = x,a . d - X,a . D
// converted to the local frame (t1, t2, n) with the reference Jacobian (shell_element.hpp), then
// the resultant law (shell_law.hpp). Total Lagrangian; the tangent is the exact second derivative
// of the discrete energy, including the geometric terms and the second variation of the
// director, 1/2 (theta x (theta' x d) + theta' x (theta x d)) = -(theta . theta') d for rotations
// orthogonal to d. EAS membrane (eas_membrane.hpp): local membrane strains E_m = E_m,c(q) + G alpha
// with G independent of q; the resultant law is linear, so the energy is quadratic in alpha and
// alpha is condensed exactly per call: with H = int G^T A_mm G dA, b = int G^T (A_R R_c)_m dA,
// L = db/dq, alpha = -H^-1 b, W = W_c - 1/2 b^T H^-1 b, force = int B^T S dA and tangent =
// int B^T C B dA + K_geo(S) - L^T H^-1 L, S the resultants of the enhanced strains. Linear mode:
// the same routine evaluated at the reference state (K0 = B0^T C B0, no initial stress), applied to
// q (shell_element.hpp).
#pragma once

#include <string>

#include "shell/shape4.hpp"
#include "shell/shell_element.hpp"

namespace si {

enum class ShearTreatment { kMitc4, kPlain };

// Membrane strains: the compatible (bilinear) field, or that field plus the EAS-4 enhancement
// (eas_membrane.hpp) whose 4 parameters are condensed exactly in every call (no element state).
enum class MembraneTreatment { kBilinear, kEas4 };

struct Quad4Options {
  std::string name;
  ShapeSet shape = ShapeSet::kBilinear;
  ShearTreatment shear = ShearTreatment::kMitc4;
  int gauss_points = 2;  // per direction: 2 or 4
  MembraneTreatment membrane = MembraneTreatment::kBilinear;
};

Quad4Options mitc4_options();        // "mitc4": MITC4 shear + EAS-4 membrane (the default)
Quad4Options mitc4_plain_options();  // "mitc4-plain": MITC4 shear, bilinear membrane
Quad4Options bernstein4_options();

class Quad4Shell : public ShellElement {
 public:
  explicit Quad4Shell(Quad4Options options);
  std::string name() const override { return options_.name; }
  void compute(const ElementGeometry& geometry, const std::array<NodeState, 4>& nodes,
               const ShellLaw& law, Kinematics kinematics, const ElementRequest& request,
               ElementResponse& response) const override;
  ElementStrains strains_at_nodes(const ElementGeometry& geometry,
                                  const std::array<NodeState, 4>& nodes,
                                  Kinematics kinematics) const override;

 private:
  // The one compute path (nonlinear strains at the given state); the linear mode calls it at
  // the reference state.
  void compute_at_state(const ElementGeometry& geometry, const std::array<NodeState, 4>& nodes,
                        const ShellLaw& law, const ElementRequest& request,
                        ElementResponse& response) const;

  Quad4Options options_;
};

}  // namespace si
