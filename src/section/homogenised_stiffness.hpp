// The 3-D stiffness of a stack of plies and its homogenisation, for the local contact laws
// (docs/theory/local-indentation.md section 6).
//
// laminate_layers: the plies of a slice z_bottom < x3 < z_top of the laminate (x3 from the
// mid-surface, laminate.hpp; plies cut by the slice keep the part inside), bottom first, each
// with its 3-D stiffness rotated to plate axes (material/ply_rotation.hpp), Voigt order
// [11, 22, 33, 23, 13, 12], MPa.
//
// homogenised_stiffness: the effective stiffness of the stack repeated periodically, exact for
// fields uniform on the scale of the period (Postma 1955, Geophysics 20:780, for isotropic
// layers; Sun & Li 1988, J. Compos. Mater. 22:629, for anisotropic plies). Perfect bonding makes
// the in-plane strains c_p = [e11, e22, g12] and the out-of-plane tractions c_t = [s33, s23, s13]
// the same in every ply, and the homogenised [s11, s22, s12] and [e33, g23, g13] the thickness
// averages of the plies'. Writing each ply's law in these mixed variables,
//     [s_p]   [ C_pp - C_pt C_tt^-1 C_tp    C_pt C_tt^-1 ] [e_p]
//     [e_t] = [ -C_tt^-1 C_tp               C_tt^-1      ] [s_t],
// the homogenised mixed matrix is the thickness average of the plies' and converts back to a
// stiffness by the same partial inversion. Its plane-stress reduction is A/h of classical
// laminate theory, and its C33 at zero in-plane strain the harmonic mean of the plies' C33.
#pragma once

#include <vector>

#include "core/linalg.hpp"
#include "section/laminate.hpp"

namespace si {

struct LayerStiffness {
  Matrix6d C;            // plate axes, Voigt [11, 22, 33, 23, 13, 12], MPa
  double thickness = 0;  // mm
};

// Throws an input si::Error unless -h/2 <= z_bottom < z_top <= h/2.
std::vector<LayerStiffness> laminate_layers(const Laminate& laminate, double z_bottom,
                                            double z_top);

// Throws an input si::Error for an empty stack or a non-positive thickness.
Matrix6d homogenised_stiffness(const std::vector<LayerStiffness>& layers);

}  // namespace si
