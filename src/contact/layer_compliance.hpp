// The normal surface compliance of a stack of anisotropic elastic layers under a periodic normal
// pressure, by the Stroh state-space (transfer-matrix) method, for the finite-thickness local
// contact laws (docs/theory/local-indentation.md section 6.3).
//
// A pressure p cos(k e.x) on the top face, e = (cos phi, sin phi, 0), displaces the face by
// H p / k cos(k e.x) along -n (n = e3, the outward normal), H in 1/MPa. Within a layer the fields
// are U(x3) exp(i k e.x); the displacement U and the traction s = sigma . n / k on planes
// x3 = const obey, with zeta = k x3 (Stroh 1962; Ting, Anisotropic Elasticity, 1996, ch. 5),
//     d/dzeta [U ; s] = [ -i T^-1 R^T          T^-1   ] [U ; s],
//                       [ Q - R T^-1 R^T   -i R T^-1 ]
// Q = (e e), R = (e n), T = (n n) (material/stiffness_contraction.hpp). The layers are stacked
// bottom first; the state is carried from the bottom up by exp of this matrix
// (core/matrix_exponential.hpp) over steps of at most one unit of zeta, the 3-dimensional space of
// states that satisfy the bottom's conditions kept as an orthonormal basis (re-orthonormalised
// after each step: the growing and decaying exponentials would otherwise swamp each other; the
// compound-matrix idea of Ng & Reid 1979, here by QR). At the top, U = Y s and H = Y33.
//
// Bottoms: a rigid base bonded to the stack (U = 0) or frictionless (U3 = 0, s1 = s2 = 0); or
// the free plate, whose bottom face is traction-free (s = 0), which reports the displacement of
// its top face, of its mid-plane and its thickness average (the last by the exponential of the
// bordered matrix [[A, 0], [[I 0], 0]], whose lower-left block is int exp(A z) dz: Van Loan 1978).
// Checked against the closed forms for an isotropic layer (Chen & Engel 1972's kernels), the
// Barnett-Lothe half-space compliance (anisotropic_half_space.hpp) at k h >> 1 and the plate's
// Kirchhoff and VAM limits at k h << 1 (tests/contact/test_layer_compliance.cpp).
#pragma once

#include <vector>

#include "section/homogenised_stiffness.hpp"

namespace si {

enum class LayerBase { kBonded, kFrictionless };

// H of the stack on a rigid base, 1/MPa. wavenumber k > 0 (1/mm).
double layer_normal_compliance(const std::vector<LayerStiffness>& layers, LayerBase base,
                               double phi_rad, double wavenumber);

// The free plate loaded on its top face: H of the top face, of the mid-plane and of the
// thickness-average normal displacement, 1/MPa (each positive along -n).
struct PlateFaceCompliance {
  double top = 0;
  double mid = 0;
  double average = 0;
};
PlateFaceCompliance plate_face_compliance(const std::vector<LayerStiffness>& layers, double phi_rad,
                                          double wavenumber);
// Its top face's alone (no mid-plane, no thickness integral: a 6 x 6 exponential per step
// instead of the bordered 9 x 9), 1/MPa.
double plate_top_compliance(const std::vector<LayerStiffness>& layers, double phi_rad,
                            double wavenumber);

}  // namespace si
