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
  if (state.d3R)
    for (auto& d3 : *mid.d3R) d3 = (T * d3).eval();
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

// The refinement of the header. Y_b = X D_b^T A (2 x 6), the transverse shear strain per unit
// R_,b of the Reissner-Mindlin plate without load coupling, about the mid-surface (vam.md 6.2):
// gamma = Y_1 R_,1 + Y_2 R_,2.
std::array<Eigen::Matrix<double, 2, 6>, 2> shear_rotation_maps(const VamSection& section) {
  const Matrix6d T = mid_surface_strain_map(section.reference_offset);
  const Matrix6d Tinv = T.inverse();
  const Matrix6d A_mid = Tinv.transpose() * section.A_R * Tinv;  // A_ref = T^T A_mid T
  const Matrix2d X = section.G.inverse();
  Eigen::Matrix<double, 2, 6> D1tA, D2tA;
  D1tA << A_mid.row(3), A_mid.row(4);  // D1: k11 <- (2g13),1 and k12+k21 <- (2g23),1
  D2tA << A_mid.row(4), A_mid.row(5);  // D2: k12+k21 <- (2g13),2 and k22 <- (2g23),2
  return {X * D1tA, X * D2tA};
}

// Plane-stress (sigma33 = 0) in-plane stiffness of the ply, [11, 12, 22]: the stress of an
// in-plane strain whose sigma33 the next-order warping would relax (monoclinic: no 13, 23 terms).
Matrix3d in_plane_stiffness(const Matrix6d& C) {
  const int in[3] = {0, 1, 2};
  Matrix3d Q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Q(i, j) = C(in[i], in[j]) - C(in[i], 5) * C(5, in[j]) / C(5, 5);
  return Q;
}

// d2(a, b) = R_,ab from R_,11, R_,12, R_,22; d3(a, b, c) from R_,111, R_,112, R_,122, R_,222.
const Vector6d& second(const std::array<Vector6d, 3>& d2, int a, int b) {
  return d2[a + b];
}
const Vector6d& third(const std::array<Vector6d, 4>& d3, int a, int b, int c) {
  return d3[a + b + c];
}

// The in-plane strain refinement at `pt` for one slice of derivatives: R_,ba = d(b, a) (or, for the
// x_c-derivative of the refinement, R_,bac) and gamma_,a = dgamma[a] (gamma_,ac):
//   Gamma_l1 V1b R_,b1 + Gamma_l2 V1b R_,b2 - x3 [g1,1, g1,2 + g2,1, g2,2],
// the last term being Gamma_l applied to the mean shear rotation w_a = -x3 gamma_a that V1b
// carries and the Reissner-Mindlin curvature already holds (header).
template <class Derivative>
Vector3d in_plane_refinement(const VamSection& section, const NormalLinePoint& pt, Derivative d,
                             const std::array<Vector2d, 2>& dgamma) {
  const int rows = 3 * (section.mesh.order() + 1);
  Vector6d Gamma = Vector6d::Zero();
  for (int b = 0; b < 2; ++b) {
    const Eigen::MatrixXd V = section.warpings.V1[b].middleRows(pt.first_dof, rows);
    for (int a = 0; a < 2; ++a) Gamma += gamma_l(pt, a) * (V * d(b, a));
  }
  const Vector3d rotation(dgamma[0](0), dgamma[1](0) + dgamma[0](1), dgamma[1](1));
  return Gamma.head<3>() - pt.x3 * rotation;
}

// gamma_,a = Y_1 R_,1a + Y_2 R_,2a (header).
std::array<Vector2d, 2> shear_gradient(const PlateState& mid,
                                       const std::array<Eigen::Matrix<double, 2, 6>, 2>& Y) {
  std::array<Vector2d, 2> out;
  for (int a = 0; a < 2; ++a)
    out[a] = Y[0] * second(*mid.d2R, 0, a) + Y[1] * second(*mid.d2R, 1, a);
  return out;
}

// gamma_,ac for c fixed: Y_1 R_,1ac + Y_2 R_,2ac.
std::array<Vector2d, 2> shear_second_gradient(const PlateState& mid,
                                              const std::array<Eigen::Matrix<double, 2, 6>, 2>& Y,
                                              int c) {
  std::array<Vector2d, 2> out;
  for (int a = 0; a < 2; ++a)
    out[a] = Y[0] * third(*mid.d3R, 0, a, c) + Y[1] * third(*mid.d3R, 1, a, c);
  return out;
}

// In-plane stress refinement at `pt` (header), [11, 12, 22].
Vector3d refined_in_plane_stress(const VamSection& section, const PlateState& mid,
                                 const NormalLinePoint& pt,
                                 const std::array<Eigen::Matrix<double, 2, 6>, 2>& Y) {
  const Vector3d Gamma = in_plane_refinement(
      section, pt, [&](int b, int a) { return second(*mid.d2R, b, a); }, shear_gradient(mid, Y));
  return in_plane_stiffness(section.mesh.ply_stiffness(pt.ply)) * Gamma;
}

// -int_{-h/2}^{x3} d_b (delta sigma_ab) dz for a = 1, 2: the transverse shear of the refined
// in-plane stresses' equilibrium, exact by Gauss-Legendre element by element.
Vector2d refined_transverse_shear(const VamSection& section, const PlateState& mid,
                                  const NormalLinePoint& target,
                                  const std::array<Eigen::Matrix<double, 2, 6>, 2>& Y) {
  const NormalLineMesh& mesh = section.mesh;
  const GaussRule rule = gauss_legendre(mesh.order() + 2);
  const std::array<Vector2d, 2> d2gamma[2] = {shear_second_gradient(mid, Y, 0),
                                              shear_second_gradient(mid, Y, 1)};
  Vector2d integral = Vector2d::Zero();
  for (int e = 0; e <= target.element; ++e) {
    const NormalLineElement& el = mesh.elements()[e];
    const double upper = (e == target.element) ? target.x3 : el.top;
    const double half = 0.5 * (upper - el.bottom);
    for (size_t g = 0; g < rule.points.size(); ++g) {
      const double z = el.bottom + half * (1.0 + rule.points[g]);
      const double xi = (2.0 * z - el.top - el.bottom) / (el.top - el.bottom);
      const NormalLinePoint pt = mesh.element_point(e, xi);
      const Matrix3d Q = in_plane_stiffness(mesh.ply_stiffness(pt.ply));
      // d_c of the refined in-plane stress, c = 1, 2: Q Gamma(R_,bac, gamma_,ac).
      Vector3d ds[2];
      for (int c = 0; c < 2; ++c)
        ds[c] = Q * in_plane_refinement(
                        section, pt, [&](int b, int a) { return third(*mid.d3R, b, a, c); },
                        d2gamma[c]);
      // [11, 12, 22]: sigma13 <- s11,1 + s12,2, sigma23 <- s12,1 + s22,2.
      integral(0) += rule.weights[g] * half * (ds[0](0) + ds[1](1));
      integral(1) += rule.weights[g] * half * (ds[0](1) + ds[1](2));
    }
  }
  return -integral;
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

RecoveredPoint recover_point(const VamSection& section, const PlateState& state, int ply, double x3,
                             EquilibriumCheck check) {
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
  if (mid.d2R) {
    const auto Y = shear_rotation_maps(section);
    out.stress.head<3>() += refined_in_plane_stress(section, mid, pt, Y);
    if (mid.d3R) out.stress.segment<2>(3) += refined_transverse_shear(section, mid, pt, Y);
  }
  out.warping = shape_matrix(pt) * V;
  if (mid.d2R && check == EquilibriumCheck::kComputed)
    out.sigma33_equilibrium = sigma33_by_equilibrium(section, mid, pt);
  return out;
}

std::vector<RecoveredPoint> recover_through_thickness(const VamSection& section,
                                                      const PlateState& state, int points_per_ply,
                                                      EquilibriumCheck check) {
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
      points.push_back(recover_point(section, state, k, x3, check));
    }
  }
  return points;
}

}  // namespace si
