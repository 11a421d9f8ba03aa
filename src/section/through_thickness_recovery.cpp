#include "section/through_thickness_recovery.hpp"

#include <string>

#include "core/error.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

// The state moved to the mid-surface, about which the warpings were computed (vam.md 6.5).
PlateState to_mid_surface(const VamSection& section, const PlateState& state) {
  const Matrix6d T = mid_surface_strain_map(section.reference_offset);
  PlateState mid = state;
  mid.R = T * state.R;
  for (int a = 0; a < 2; ++a) mid.dR[a] = T * state.dR[a];
  if (state.d2R)
    for (auto& d2 : *mid.d2R) d2 = (T * d2).eval();
  return mid;
}

int element_dofs(const VamSection& section) {
  return 3 * (section.mesh.order() + 1);
}

// The warping DOFs of the element containing `pt` (vam.md 8, first line).
Eigen::VectorXd element_warping(const VamSection& section, const PlateState& mid,
                                const NormalLinePoint& pt) {
  const int d = pt.first_dof;
  const int m = element_dofs(section);
  const VamWarpings& w = section.warpings;
  return w.V0.middleRows(d, m) * mid.R + w.V1[0].middleRows(d, m) * mid.dR[0] +
         w.V1[1].middleRows(d, m) * mid.dR[1] + w.VL_top.segment(d, m) * mid.t_top +
         w.VL_bottom.segment(d, m) * mid.t_bottom;
}

// sigma13,1 + sigma23,2 at `pt` from the first-order stress per unit R_,b,
// r_b = C_k (Gamma_h V1b + Gamma_lb V0) (vam.md 8, recommended sigma33 form).
double transverse_shear_divergence(const VamSection& section, const NormalLinePoint& pt,
                                   const std::array<Vector6d, 3>& d2R) {
  const int d = pt.first_dof;
  const int m = element_dofs(section);
  const Matrix6d& C = section.mesh.ply_stiffness(pt.ply);
  const Eigen::MatrixXd V0 = section.warpings.V0.middleRows(d, m);
  const Eigen::MatrixXd Bh = gamma_h(pt);
  double divergence = 0;
  for (int b = 0; b < 2; ++b) {
    const Matrix6d r = C * (Bh * section.warpings.V1[b].middleRows(d, m) + gamma_l(pt, b) * V0);
    // d2R holds R_,11, R_,12, R_,22: R_,b1 is entry b and R_,b2 is entry b + 1.
    divergence += r.row(3).dot(d2R[b]) + r.row(4).dot(d2R[b + 1]);
  }
  return divergence;
}

// -t- - int_{-h/2}^{x3} (sigma13,1 + sigma23,2) dz, exact by Gauss-Legendre element by element.
double sigma33_by_equilibrium(const VamSection& section, const PlateState& mid,
                              const NormalLinePoint& target) {
  const NormalLineMesh& mesh = section.mesh;
  const GaussRule rule = gauss_legendre(mesh.order() + 2);
  double integral = 0;
  for (int e = 0; e <= target.element; ++e) {
    const NormalLineElement& el = mesh.elements()[e];
    const double upper = (e == target.element) ? target.x3 : el.top;
    const double half = 0.5 * (upper - el.bottom);
    for (size_t g = 0; g < rule.points.size(); ++g) {
      const double z = el.bottom + half * (1.0 + rule.points[g]);
      const double xi = (2.0 * z - el.top - el.bottom) / (el.top - el.bottom);
      integral += rule.weights[g] * half *
                  transverse_shear_divergence(section, mesh.element_point(e, xi), *mid.d2R);
    }
  }
  return -mid.t_bottom - integral;
}

}  // namespace

RecoveredPoint recover_point(const VamSection& section, const PlateState& state, int ply,
                             double x3) {
  const PlateState mid = to_mid_surface(section, state);
  const NormalLinePoint pt = section.mesh.point(x3, ply);
  const Eigen::VectorXd V = element_warping(section, mid, pt);
  const Eigen::MatrixXd V0 = section.warpings.V0.middleRows(pt.first_dof, element_dofs(section));

  RecoveredPoint out;
  out.ply = ply;
  out.x3 = x3;
  out.strain = gamma_eps(x3) * mid.R + gamma_h(pt) * V + gamma_l(pt, 0) * V0 * mid.dR[0] +
               gamma_l(pt, 1) * V0 * mid.dR[1];
  out.stress = section.mesh.ply_stiffness(ply) * out.strain;
  out.warping = shape_matrix(pt) * V;
  if (mid.d2R) out.sigma33_equilibrium = sigma33_by_equilibrium(section, mid, pt);
  return out;
}

std::vector<RecoveredPoint> recover_through_thickness(const VamSection& section,
                                                      const PlateState& state, int points_per_ply) {
  if (points_per_ply < 2)
    throw_input("through-thickness recovery needs at least 2 points per ply (both ply faces)",
                Where{"", "points_per_ply", std::to_string(points_per_ply), 0});
  std::vector<RecoveredPoint> points;
  const std::vector<double>& z = section.mesh.interfaces();
  for (int k = 0; k < section.mesh.plies(); ++k) {
    const double bottom = z[k], top = z[k + 1];
    for (int i = 0; i < points_per_ply; ++i) {
      const double x3 =
          (i + 1 == points_per_ply) ? top : bottom + (top - bottom) * i / (points_per_ply - 1.0);
      points.push_back(recover_point(section, state, k, x3));
    }
  }
  return points;
}

}  // namespace si
