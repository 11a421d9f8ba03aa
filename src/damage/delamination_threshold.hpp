// Closed-form quasi-static delamination threshold load of a laminated plate under a concentrated
// transverse load (Davies & Zhang, "Impact damage prediction in carbon composite structures",
// Int. J. Impact Eng. 16 (1995) 149-170):
//   P_c^2 = 8 pi^2 E h^3 G_IIc / (9 (1 - nu^2))   (isotropic plate, one mid-plane delamination)
// i.e. P_c = pi sqrt(32 D G_IIc / 3) with D = E h^3 / (12 (1 - nu^2)). It follows from the
// compliance change of a circular mid-plane delamination of radius a under the load: inside it the
// plate bends as two halves of stiffness D/8 each, the energy release rate is
// G = 3 P^2 / (32 pi^2 D), independent of a (hence a threshold, not a growth law). The same
// argument with n equally spaced delaminations of equal radius gives G = (n + 2) P^2/(32 pi^2 D)
// and P_c = pi sqrt(32 D G_IIc / (n + 2)) (the form Olsson, Donadon & Falzon, IJSS 43 (2006) 3124,
// quote after Suemasu & Majima 1996); n = 1 is Davies & Zhang.
//
// For an anisotropic laminate D is replaced by an effective isotropic stiffness D*:
//   kGeometricMean: D* = sqrt(D11 D22)  (the quasi-isotropic equivalent);
//   kOlsson:        D* = sqrt(D11 D22 (A + 1)/2), A = (D12 + 2 D66)/sqrt(D11 D22) (Olsson,
//                   Compos. Part A 32 (2001) 1207; AIAA J. 30 (1992) 1587): the isotropic plate
//                   with the point-load impedance 8 sqrt(m D*) of the specially orthotropic
//                   infinite plate, whose exact D* is the angular mean
//                     D*^(-1/2) = (2/pi) int_0^(pi/2) D(t)^(-1/2) dt,
//                     D(t) = D11 c^4 + 2 (D12 + 2 D66) c^2 s^2 + D22 s^4 (c, s = cos t, sin t);
//                   the closed form is that mean to 1.5 % for 0.1 <= A <= 3, exact at A = 1
//                   (tests/damage/test_delamination_threshold.cpp).
// Both equal D for a quasi-isotropic laminate (A = 1). The D block is taken about the mid-surface
// (bending of the plate as a whole); coupling terms D16, D26 and B are ignored, as in the sources.
// Olsson et al. (2006) also give a dynamic threshold for small-mass impact (about 1.21 times the
// static one, from the wave-controlled response); it does not apply to quasi-static indentation
// and is not computed here.
#pragma once

#include "core/linalg.hpp"

namespace si {

enum class EffectiveBendingStiffness { kGeometricMean, kOlsson };

// The threshold with the inputs it used (for path.json / sweep.csv beside the computed onset).
struct DelaminationThreshold {
  double load = 0;                            // P_c, N
  double D_effective = 0;                     // D*, N mm
  double D11 = 0, D22 = 0, D12 = 0, D66 = 0;  // N mm, mid-surface bending stiffness
  double anisotropy = 0;                      // Olsson's A = (D12 + 2 D66) / sqrt(D11 D22)
  double G_IIc = 0;                           // N/mm
  int delaminations = 1;                      // n
  EffectiveBendingStiffness stiffness = EffectiveBendingStiffness::kOlsson;
};

// D is the bending block of a plate stiffness in Yu order about the mid-surface
// ([[A, B], [B^T, D]] with rows k11, k12+k21, k22: D11 = D(0,0), D66 = D(1,1), D12 = D(0,2),
// D22 = D(2,2)). Throws an input si::Error unless G_IIc > 0, delaminations >= 1 and D11, D22 > 0.
DelaminationThreshold delamination_threshold(const Matrix3d& D, double G_IIc,
                                             EffectiveBendingStiffness stiffness,
                                             int delaminations = 1);

}  // namespace si
