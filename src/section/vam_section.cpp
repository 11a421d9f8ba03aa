#include "section/vam_section.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "section/warping_solver.hpp"

namespace si {
namespace {

constexpr int kMaxOrder = 8;  // equally spaced Lagrange nodes get ill-conditioned beyond this,
                              // and p = 3 is already exact (vam.md 4.1)
constexpr double kStructureTolerance = 1e-12;  // vam.md 5.3

void validate_options(const VamOptions& options) {
  if (options.order < 2 || options.order > kMaxOrder)
    throw_input("the VAM normal-line element order must be between 2 and " +
                    std::to_string(kMaxOrder) + " (4 recommended)",
                Where{"", "vam.order", std::to_string(options.order), 0});
  if (options.elements_per_ply < 1)
    throw_input("the VAM analysis needs at least one normal-line element per ply",
                Where{"", "vam.elements_per_ply", std::to_string(options.elements_per_ply), 0});
}

// Monoclinic about x3 (vam.md 1): C_yu couples {11, 12, 22, 33} and {13, 23} only. Every ply
// rotated about the normal is; the simplifications of vam.md 5.3 and 6.2 rely on it.
void require_monoclinic(const Laminate& laminate) {
  for (size_t k = 0; k < laminate.plies.size(); ++k) {
    const Matrix6d C = laminate.plies[k].stiffness_yu();
    const double scale = C.cwiseAbs().maxCoeff();
    for (int i : {0, 1, 2, 5})
      for (int j : {3, 4})
        if (std::abs(C(i, j)) > kStructureTolerance * scale)
          throw_input("ply " + std::to_string(k + 1) +
                      " is not monoclinic about the plate normal; such laminates are outside "
                      "the scope of the VAM plate analysis (vam.md 5.3)");
  }
}

// Balances membrane and curvature entries (T_kappa = sqrt(12)/h, vam.md 6.3) so that the checks
// below compare numbers of one dimension.
Vector6d balance(double h) {
  Vector6d T = Vector6d::Ones();
  T.tail<3>().setConstant(std::sqrt(12.0) / h);
  return T;
}

// vam.md 5.3 and 6.2: B_a = 0 and row 2 of K~^T Dbar_a = 0 for monoclinic plies. Anything else
// means the laminate is outside the scope of this analysis (or the numerics failed).
void require_first_order_structure(const NormalLineMesh& mesh, const NormalLineMatrices& m,
                                   const Eigen::MatrixXd& V0, const Matrix6d& A_mid) {
  const double h = mesh.thickness();
  const Vector6d t = balance(h);
  const auto T = t.asDiagonal();
  const double scale = (T * A_mid * T).norm();
  const Eigen::MatrixXd K = mesh.kernel();
  for (int a = 0; a < 2; ++a) {
    const double cross = (T * first_order_cross_term(m, V0, a) * T).norm() / h;
    const double w3_shift = (K.col(2).transpose() * first_order_load(m, V0, a) * T).norm();
    if (cross > kStructureTolerance * scale || w3_shift > kStructureTolerance * scale) {
      std::ostringstream os;
      os << "the first-order VAM cross terms do not vanish (|B| = " << cross
         << ", |K^T Dbar row 2| = " << w3_shift << ", relative to |A| = " << scale
         << "); the laminate is outside the scope of the VAM plate analysis (vam.md 5.3)";
      throw_numerical(os.str());
    }
  }
}

// Unit load vector on the w3 DOF of a face node (vam.md 7.1).
Eigen::VectorXd face_load(const NormalLineMesh& mesh, int w3_dof) {
  Eigen::VectorXd L = Eigen::VectorXd::Zero(mesh.dofs());
  L(w3_dof) = 1.0;
  return L;
}

// 12 x 12 gradient energy H_ab = V0^T D_ab V0 - V1a^T E V1b (vam.md 6.1), H11, H22 symmetrised,
// H12 kept as computed (it is strongly non-symmetric, vam.md 13).
Eigen::MatrixXd gradient_energy(const NormalLineMatrices& m, const Eigen::MatrixXd& V0,
                                const std::array<Eigen::MatrixXd, 2>& V1) {
  Eigen::MatrixXd H(12, 12);
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      H.block<6, 6>(6 * a, 6 * b) =
          V0.transpose() * m.D_ll[a][b] * V0 - V1[a].transpose() * m.E * V1[b];
  for (int a = 0; a < 2; ++a) {
    const Matrix6d block = H.block<6, 6>(6 * a, 6 * a);
    H.block<6, 6>(6 * a, 6 * a) = 0.5 * (block + block.transpose());
  }
  H.block<6, 6>(6, 0) = H.block<6, 6>(0, 6).transpose();
  return H;
}

}  // namespace

Eigen::MatrixXd first_order_load(const NormalLineMatrices& m, const Eigen::MatrixXd& V0,
                                 int alpha) {
  return (m.D_h[alpha] - m.D_h[alpha].transpose()) * V0 - m.D_le[alpha];
}

Matrix6d first_order_cross_term(const NormalLineMatrices& m, const Eigen::MatrixXd& V0, int alpha) {
  return V0.transpose() * m.D_h[alpha] * V0 + m.D_le[alpha].transpose() * V0;
}

Matrix6d mid_surface_strain_map(double reference_offset) {
  Matrix6d T = Matrix6d::Identity();
  T.topRightCorner<3, 3>() = -reference_offset * Eigen::Matrix3d::Identity();
  return T;
}

VamSection analyze_vam(const Laminate& laminate, const VamOptions& options) {
  validate_options(options);
  laminate.validate();
  require_monoclinic(laminate);

  NormalLineMesh mesh(laminate, options.order, options.elements_per_ply);
  const NormalLineMatrices m = assemble_normal_line(mesh);
  const WarpingSolver solver(m.E, m.H_psi);

  // Zeroth order (vam.md 5.1): the classical stiffness about the mid-surface.
  VamWarpings warpings;
  warpings.V0 = solver.solve(m.D_he);
  Matrix6d A_mid = m.D_ee + warpings.V0.transpose() * m.D_he;
  A_mid = (0.5 * (A_mid + A_mid.transpose())).eval();
  require_first_order_structure(mesh, m, warpings.V0, A_mid);

  // Normal face tractions (vam.md 7.1-7.3). Fbar = -V0^T L, the face w3 per unit strain.
  const int top_w3 = mesh.dofs() - 1;
  const int bottom_w3 = 2;
  warpings.VL_top = solver.solve(-face_load(mesh, top_w3));
  warpings.VL_bottom = solver.solve(-face_load(mesh, bottom_w3));
  const Vector6d Fbar_top_mid = -warpings.V0.row(top_w3).transpose();
  const Vector6d Fbar_bottom_mid = -warpings.V0.row(bottom_w3).transpose();
  Matrix2d c_L;
  c_L << warpings.VL_top(top_w3), warpings.VL_bottom(top_w3), warpings.VL_top(bottom_w3),
      warpings.VL_bottom(bottom_w3);

  // First order (vam.md 6.1) and the Reissner-Mindlin fit (6.2-6.4), about the mid-surface.
  std::array<ShearRelaxation, 2> S;
  for (int a = 0; a < 2; ++a) {
    const Eigen::MatrixXd Dbar = first_order_load(m, warpings.V0, a);
    warpings.V1[a] = solver.solve(Dbar);
    S[a] = (mesh.kernel().transpose() * Dbar).topRows<2>();
  }
  const Eigen::MatrixXd H = gradient_energy(m, warpings.V0, warpings.V1);
  const ReissnerMindlinFit fit =
      fit_reissner_mindlin(A_mid, H, S, mesh.thickness(), options.compat_fit);

  // Move the classical stiffness and the load coupling to the reference surface (vam.md 6.5).
  const Matrix6d T = mid_surface_strain_map(laminate.reference_offset);
  return VamSection{laminate.reference_offset,
                    T.transpose() * A_mid * T,
                    fit.G,
                    T.transpose() * Fbar_top_mid,
                    T.transpose() * Fbar_bottom_mid,
                    c_L,
                    H,
                    fit.diagnostics,
                    std::move(mesh),
                    std::move(warpings)};
}

}  // namespace si
