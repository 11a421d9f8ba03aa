// A rigid or elastic sphere on the plane face of an anisotropic elastic half-space: the surface
// compliance of the half-space and the indentation moduli of the local contact law `anisotropic`
// (docs/theory/local-indentation.md section 6.2). The half-space is x3 < 0, its face x3 = 0 with
// the outward normal n = e3 (the laminate's outer face); C its 3-D stiffness in plate axes,
// Voigt order [11, 22, 33, 23, 13, 12], MPa.
//
// Surface compliance. A normal pressure p cos(k e.x) on the face, e = (cos phi, sin phi, 0),
// displaces it by H(phi) p / k cos(k e.x) along -n, with
//     H(phi) = n . L(phi)^-1 . n,
//     L(phi) = (1/pi) int_0^pi [ (mm) - (mq)(qq)^-1(qm) ] dw,
//     m = cos w e + sin w n,  q = -sin w e + cos w n,
// L the Barnett-Lothe tensor of the sagittal plane (e, n) (Barnett & Lothe 1975, Phys. Norv. 8:13;
// Ting, Anisotropic Elasticity, 1996, eq. 7.6-4; (ab) of material/stiffness_contraction.hpp). It
// is the Fourier form of the surface Green's function: the face's response to a line load along
// e x n is -(1/pi) L^-1 ln|x|. H is real, positive and pi-periodic; for an isotropic solid
// H = 2 (1 - nu^2) / E, for a transversely isotropic one with its axis along n a constant. The
// integrand is smooth and periodic in w, so the trapezoidal rule converges geometrically; it is
// doubled until H changes by less than 1e-15.
//
// Indentation moduli. The half-space's normal surface displacement under a point force P is
// P w(theta) / r with w(theta) = H(theta + pi/2) / (2 pi) (the Radon form of the Fourier
// compliance H / k):
//  * Vlassak & Nix (1993, Phil. Mag. A 67:1045; 1994, J. Mech. Phys. Solids 42:1223) replace w by
//    its average over theta, an isotropic half-space of indentation modulus M = 2 / <H>: exact
//    for a circular contact when H has no second harmonic (e.g. four-fold symmetry).
//  * Willis (1966, J. Mech. Phys. Solids 14:163): a sphere of radius R makes an elliptical
//    contact with Hertz's ellipsoidal pressure p0 (1 - x^T A^-1 x / c^2)^0.5 (A = A^T, det A = 1),
//    under which the face inside the ellipse displaces by
//        u(x) = (c^2 p0 / 8) int_0^2pi H(phi) / s [1 - (e.x)^2 / s^2] dphi,   s = c (e^T A e)^0.5
//    (derived in local-indentation.md 6.2). u = alpha - |x|^2 / (2R) fixes the shape A by
//    K = int H e e^T / s^3 dphi proportional to the identity, and then
//        F = (4/3) E_W R^0.5 alpha^1.5,   E_W = 2^(5/2) pi J2^(1/2) J0^(-3/2),
//        J0 = int_0^2pi H / s dphi,  J2 = K11 = K22  (A normalised to det 1, c = 1).
//    For isotropic H both give Hertz's E / (1 - nu^2).
#pragma once

#include "core/linalg.hpp"

namespace si {

// H(phi) above, 1/MPa. quadrature: the trapezoidal rule's first number of points on [0, pi)
// (>= 8), doubled until converged.
double half_space_normal_compliance(const Matrix6d& C, double phi_rad, int quadrature = 64);

struct HalfSpaceIndentation {
  double vlassak_nix = 0;     // M = 2 / <H>, MPa
  double willis = 0;          // E_W, MPa: F = (4/3) E_W R^0.5 alpha^1.5
  double aspect = 1;          // b / a <= 1 of Willis' contact ellipse
  double major_axis_deg = 0;  // direction of its major axis from x1 towards x2, (-90, 90]
};

// The moduli from H sampled at `directions` angles in [0, pi) (>= 8). extra_compliance (1/MPa)
// is added to H at every angle: an isotropic elastic indenter's 2 (1 - nu_i^2) / E_i (its own
// half-space compliance; Hertz's 1/E* sums the two bodies'). Throws a numerical si::Error if
// Willis' shape does not converge.
HalfSpaceIndentation half_space_indentation(const Matrix6d& C, double extra_compliance = 0.0,
                                            int directions = 64);

}  // namespace si
