// Variational-asymptotic (VAM) through-thickness analysis of a flat laminated plate: the
// Reissner-Mindlin plate law with normal-traction coupling (Yu, Hodges & Volovoi, IJSS 39 (2002)
// 5185; Comput. Struct. 81 (2003) 439), as reconstructed in shared/docs/vam.md sections 4-8.
//
// The 2-D energy density per unit reference area is (vam.md 7.4)
//   Pi = 1/2 R^T A_R R + 1/2 gamma^T G gamma + R^T (t+ Fbar_top + t- Fbar_bottom)
//        - (t+ + t-) u3 - 1/2 t^T c_L t,          t = [t+, t-]
// with the Yu orderings
//   R     = [e11, 2 e12, e22, k11, k12 + k21, k22]   (conjugate [N11, N12, N22, M11, M12, M22])
//   gamma = [2 g13, 2 g23]                           (conjugate [Q1, Q2])
// and t+ / t- the normal tractions on the top / bottom face, positive along +x3 (an indenter
// pressure p on the top face is t+ = -p). u3 is the thickness-average deflection; the top face
// moves by U3(h/2) = u3 - R^T Fbar_top + c_L(0,0) t+ + c_L(0,1) t- (vam.md 7.4).
//
// Curvature of a shell is not included (flat-plate analysis, vam.md 9.2). Units: mm, N, MPa.
#pragma once

#include <array>

#include "core/linalg.hpp"
#include "section/laminate.hpp"
#include "section/normal_line_mesh.hpp"
#include "section/reissner_mindlin_fit.hpp"

namespace si {

struct VamOptions {
  int order = 4;             // Lagrange order p of the normal-line elements: >= 2 (A_R, Fbar,
                             // c_L exact), >= 3 for the exact H and G (vam.md 4.1)
  int elements_per_ply = 1;  // >= 1
  bool compat_fit = false;   // add the curvature-compatibility freedom to the RM fit (6.4.1)
};

// Warping solutions about the mid-surface, kept for the 3-D recovery (vam.md 8). Each is a
// column set of normal-line DOFs (see normal_line_mesh.hpp) with zero thickness average.
struct VamWarpings {
  Eigen::MatrixXd V0;                 // n x 6, per unit R (zeroth order, vam.md 5.1)
  std::array<Eigen::MatrixXd, 2> V1;  // n x 6 each, per unit R_,1 and R_,2 (vam.md 6.1)
  Eigen::VectorXd VL_top;             // per unit t+ (vam.md 7.1)
  Eigen::VectorXd VL_bottom;          // per unit t-
};

struct VamSection {
  double reference_offset;  // mm above the mid-surface; A_R and Fbar refer to this surface
  Matrix6d A_R;             // classical stiffness [[A, B], [B^T, D]] about the reference surface
  Matrix2d G;               // transverse shear stiffness, N/mm (fit about the mid-surface)
  Vector6d Fbar_top;        // load coupling per unit t+ : [mm, mm, mm, mm^2, mm^2, mm^2]
  Vector6d Fbar_bottom;     // load coupling per unit t-
  Matrix2d c_L;             // face compliance [[c++, c+-], [c-+, c--]], mm/MPa (vam.md 7.3)
  Eigen::MatrixXd H;        // 12 x 12 gradient energy about the mid-surface (vam.md 6.1)
  VamFitDiagnostics fit;
  NormalLineMesh mesh;
  VamWarpings warpings;
};

// Throws an input si::Error for an invalid laminate or options (order < 2, order > 8,
// elements_per_ply < 1) or a ply that is not monoclinic about x3 (outside this analysis, vam.md
// 5.3), and a numerical one if the warping system is singular or the fitted G^-1 is not SPD.
VamSection analyze_vam(const Laminate& laminate, const VamOptions& options = {});

// Steps of analyze_vam, public so that tests can check their invariants.
// Dbar_a = (D_ha - D_ha^T) V0 - D_lae, the first-order warping load (vam.md 6.1), n x 6.
Eigen::MatrixXd first_order_load(const NormalLineMatrices& m, const Eigen::MatrixXd& V0, int alpha);
// B_a = V0^T D_ha V0 + D_lae^T V0, the O(h/l) cross term; zero for monoclinic plies (vam.md 5.3).
Matrix6d first_order_cross_term(const NormalLineMatrices& m, const Eigen::MatrixXd& V0, int alpha);
// T(e) with R_mid = T R_ref for a reference surface at x3 = e: [[I, -e I], [0, I]] (vam.md 6.5).
// Quantities transform as A_ref = T^T A_mid T and Fbar_ref = T^T Fbar_mid.
Matrix6d mid_surface_strain_map(double reference_offset);

}  // namespace si
