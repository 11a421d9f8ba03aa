// Enhanced assumed strain (EAS) membrane field of the 4-node shell: the parametric modes of EAS-4
// (Simo & Rifai 1990, IJNME 29:1595-1638; Andelfinger & Ramm 1993, IJNME 36:1311-1337, their
// membrane modes; applied to Green-Lagrange shell strains by Buechter, Ramm & Roehl 1994, IJNME
// 37:2551-2568). The enhanced local membrane strains [e11, 2 e12, e22] at (xi, eta) are
//   E_enh = (det J0 / det J) M0 Gamma(xi, eta) alpha,
// with M0 the covariant-to-local map of the membrane strains at the element centre (reference
// Jacobian J0), det J0 / det J the ratio of the reference area elements at the centre and at the
// point, and Gamma the parametric modes in covariant order [E_xixi, 2 E_xieta, E_etaeta]:
//   E_xixi = xi a1,  E_etaeta = eta a2,  2 E_xieta = xi a3 + eta a4.
// Why these four: pure in-plane bending of a rectangle along xi has E_xixi ~ eta (the bilinear
// field has it), 2 E_xieta = 0 and the Poisson strain E_etaeta ~ -nu eta. The bilinear field
// cannot give the last two: its shear carries a term ~ xi (the parasitic shear that locks) and its
// E_etaeta varies with xi only. a3 cancels that shear term and a2 supplies the Poisson strain;
// a4 and a1 do the same for bending along eta. The five- and seven-mode sets add xi eta terms
// that only matter for distorted coarse meshes (Andelfinger & Ramm 1993); EAS-4 is the smallest
// set that makes rectangles exact in in-plane bending (there it is equivalent to Pian &
// Sumihara's hybrid element and to Wilson's incompatible modes as corrected by Taylor et al.
// 1976, QM6). Each mode integrates to zero over the parent square, so with the
// det J0 / det J factor the enhanced field is L2-orthogonal to any constant stress: the patch
// test is passed (alpha = 0 for constant strain).
#pragma once

#include <Eigen/Dense>

namespace si {

constexpr int kEasMembraneModes = 4;

using EasModes = Eigen::Matrix<double, 3, kEasMembraneModes>;

// Gamma(xi, eta): rows [E_xixi, 2 E_xieta, E_etaeta], one column per parameter a1..a4.
inline EasModes eas4_parametric_modes(double xi, double eta) {
  EasModes m;
  m << xi, 0, 0, 0,   //
      0, 0, xi, eta,  //
      0, eta, 0, 0;
  return m;
}

// Local membrane enhancement at (xi, eta): (det J0 / det J) M0 Gamma(xi, eta).
inline EasModes eas4_membrane_modes(const Eigen::Matrix3d& M0, double area_ratio, double xi,
                                    double eta) {
  return area_ratio * M0 * eas4_parametric_modes(xi, eta);
}

}  // namespace si
