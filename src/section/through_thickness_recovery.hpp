// 3-D recovery of strain, stress and warping through the thickness of a flat laminated plate from
// the 2-D Reissner-Mindlin solution at one point (x1, x2), with the VAM warpings of
// vam_section.hpp (Yu, Hodges & Volovoi, Comput. Struct. 81 (2003) 439; shared/docs/vam.md 8):
//   V     = V0 R + V11 R_,1 + V12 R_,2 + VL_top t+ + VL_bottom t-
//   Gamma = Gamma_eps(x3) R + Gamma_h V + Gamma_l1 V0 R_,1 + Gamma_l2 V0 R_,2,   sigma = C_k Gamma
//   w     = S(x3) V        (U_a = u_a - x3 u3_,a + w_a, U3 = u3 + w3; <w> = 0)
// The recovery is driven by R and its gradients directly (not by the classical strains
// R - D_a gamma_,a, which is much worse for thick plates, vam.md 8).
//
// Refinement (docs/theory/failure.md 3): the first-order warping V1a R_,a carries the zig-zag of
// the in-plane displacement through the plies; its in-plane derivatives are the next term of the
// in-plane strain,
//   Gamma_in += Gamma_l1 V~1b R_,b1 + Gamma_l2 V~1b R_,b2,
// where V~1b is V1b less the mean shear rotation x3 gamma that the Reissner-Mindlin curvature
// beta_a,b already carries, with gamma = X (D1^T A R_,1 + D2^T A R_,2), the Reissner-Mindlin
// equilibrium without load coupling (vam.md 6.2; using a 2-D solution's own gamma, which carries
// the load coupling Fbar t, was tried and is worse at S = 4, docs/theory/failure.md). It is added
// when the second derivatives R_,ab are given; the transverse shear stresses then follow from the
// 3-D equilibrium of the corrected in-plane stresses when the third derivatives are given too.
//
// Orderings: R = [e11, 2e12, e22, k11, k12+k21, k22]; Gamma and sigma are
// [11, 12, 22, 13, 23, 33] with engineering shear strains. x3 is measured from the mid-surface
// (as Laminate::interfaces()); R and its derivatives refer to the laminate's reference surface.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "core/linalg.hpp"
#include "section/vam_section.hpp"

namespace si {

// The 2-D solution at one in-plane point, about the reference surface of the section.
struct PlateState {
  Vector6d R = Vector6d::Zero();                                   // RM strains
  std::array<Vector6d, 2> dR{Vector6d::Zero(), Vector6d::Zero()};  // R_,1 and R_,2, 1/mm
  double t_top = 0;     // normal traction on the top face along +x3, MPa
  double t_bottom = 0;  // normal traction on the bottom face along +x3, MPa
  // R_,11, R_,12, R_,22 (1/mm^2), e.g. from patch recovery of the 2-D field. When given, the
  // in-plane stresses carry the zig-zag refinement (header) and sigma33 is also obtained by
  // integrating the 3-D equilibrium from the bottom face.
  std::optional<std::array<Vector6d, 3>> d2R;
  // R_,111, R_,112, R_,122, R_,222 (1/mm^3). With d2R, the transverse shear stresses carry the
  // equilibrium of the refined in-plane stresses: sigma_a3 -= int_{-h/2}^{x3} d_b(delta sigma_ab).
  std::optional<std::array<Vector6d, 4>> d3R;
};

struct RecoveredPoint {
  int ply = 0;
  double x3 = 0;     // mm from the mid-surface
  Vector6d strain;   // Gamma
  Vector6d stress;   // sigma = C_k Gamma, MPa; sigma33 is the simple (linear) form of vam.md 8,
                     // in-plane and transverse shear refined when d2R (d3R) are given (header)
  Vector3d warping;  // w, mm
  // vam.md 8, recommended form: sigma33 = -t- - int_{-h/2}^{x3} (sigma13,1 + sigma23,2) dz.
  // At the top face it equals t+ only if the 2-D equilibrium holds; the difference is an error
  // indicator of the 2-D solution. Empty unless PlateState::d2R is given.
  std::optional<double> sigma33_equilibrium;
};

// Whether RecoveredPoint::sigma33_equilibrium is computed: an integral through the thickness
// below the point, half the cost of a refined recovery; a linear map built from unit states
// (analysis/damage_probe.cpp) reads the stresses only.
enum class EquilibriumCheck { kComputed, kSkipped };

// The 3-D fields at x3 inside ply `ply` (at an interface, the value on that ply's side).
// Throws an input si::Error if x3 is not inside the ply.
RecoveredPoint recover_point(const VamSection& section, const PlateState& state, int ply, double x3,
                             EquilibriumCheck check = EquilibriumCheck::kComputed);

// points_per_ply (>= 2) equally spaced points in every ply, both ply faces included, so each
// interface appears twice (once per ply); bottom ply first.
std::vector<RecoveredPoint> recover_through_thickness(
    const VamSection& section, const PlateState& state, int points_per_ply,
    EquilibriumCheck check = EquilibriumCheck::kComputed);

}  // namespace si
