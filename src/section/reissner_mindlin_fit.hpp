// Reissner-Mindlin transformation of the first-order VAM plate energy (shared/docs/vam.md
// 6.2-6.4; Yu, Hodges & Volovoi, Comput. Struct. 81 (2003) 439, eqs. 56-61 as cited by OpenSG:
// "78 equations, 27 unknowns").
//
// The asymptotic energy 2 Pi = eps^T A eps + eps'^T H eps' (eps' = [eps_,1; eps_,2]) is matched to
// the RM form R^T A R + gamma^T G gamma by choosing X = G^-1 and the free constants c1, c2 (2 x 6
// each, the freedom to redefine the in-plane displacements, V1a -> V1a + K~ ca) such that the
// residual 12 x 12 operator
//   M(X, c) = H + [A Da X Db^T A]_ab + [ca^T Sb + Sa^T cb]_ab
// is as small as possible in the least-squares sense (vam.md 6.3). The 78 equations are the upper
// triangle of M (21 + 36 + 21 entries) weighted by T_i T_j, with T = 1 for the membrane and
// sqrt(12)/h for the curvature components [choice of vam.md 6.3: fit on the balanced strains
// [eps, (h/sqrt 12) kappa], so the result does not depend on the unit system].
// The optional `compat` variant (vam.md 6.4.1) adds the curvature compatibility freedom
// R'^T (P^T K + K^T P) R' with K (2 x 12) free: 51 unknowns.
//
// Orderings: Yu, R = [e11, 2e12, e22, k11, k12+k21, k22], gamma = [2g13, 2g23].
#pragma once

#include <array>

#include "core/linalg.hpp"

namespace si {

struct VamFitDiagnostics {
  double relative_residual = 0;  // |r(x)| / |r(0)| of the weighted equations
  int rank = 0;                  // numerical rank of the equilibrated Jacobian (26 for LS78)
  int unknowns = 0;              // 27 (LS78) or 51 (compat)
  int equations = 0;             // 78
  double X_min_eigenvalue = 0;   // smallest eigenvalue of X = G^-1, mm/N (> 0: SPD)
};

struct ReissnerMindlinFit {
  Matrix2d G;  // transverse shear stiffness, N/mm, order [2g13, 2g23]
  VamFitDiagnostics diagnostics;
};

using ShearRelaxation = Eigen::Matrix<double, 2, 6>;  // S_a: rows 0, 1 of K~^T Dbar_a

// A: classical stiffness about the mid-surface; H: 12 x 12 gradient energy (vam.md 6.1);
// S: the in-plane equilibrium operators S_1, S_2 (vam.md 6.2); thickness h in mm.
// Throws a numerical si::Error if X = G^-1 is not positive definite.
ReissnerMindlinFit fit_reissner_mindlin(const Matrix6d& A, const Eigen::MatrixXd& H,
                                        const std::array<ShearRelaxation, 2>& S, double thickness,
                                        bool compat);

}  // namespace si
