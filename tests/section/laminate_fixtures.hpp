// Materials, lay-ups and the textbook classical lamination theory used as independent
// references by the section tests (shared/docs/vam.md 10.1, 11.3 and 12).
#pragma once

#include <cmath>
#include <vector>

#include "core/linalg.hpp"
#include "material/material.hpp"
#include "section/laminate.hpp"

namespace si::testing {

// Indentation-paper material of vam.md section 12 (MPa): E1 = 130, E2 = E3 = 10, G12 = 6,
// G23 = 6, G13 = 3 GPa; nu12 = 0.3, nu23 = 0.3, nu13 = 0.5. Plies are 0.475 mm.
inline Material paper_material() {
  EngineeringConstants c;
  c.E1 = 130000;
  c.E2 = c.E3 = 10000;
  c.G12 = 6000;
  c.G23 = 6000;
  c.G13 = 3000;
  c.nu12 = 0.3;
  c.nu23 = 0.3;
  c.nu13 = 0.5;
  return Material::orthotropic("paper", c);
}
constexpr double kPaperPly = 0.475;  // mm

// Pagano (1969) material of vam.md section 11.3 with E_T = 1: E_L/E_T = 25, G_LT/E_T = 0.5,
// G_TT/E_T = 0.2, nu = 0.25 for all pairs; E3 = E_T, G13 = G_LT, G23 = G_TT.
inline Material pagano_material() {
  EngineeringConstants c;
  c.E1 = 25;
  c.E2 = c.E3 = 1;
  c.G12 = c.G13 = 0.5;
  c.G23 = 0.2;
  c.nu12 = c.nu13 = c.nu23 = 0.25;
  return Material::orthotropic("pagano", c);
}

// Plies of one material and thickness, angles listed bottom to top, mid-surface reference.
inline Laminate make_laminate(const Material& material, double ply_thickness,
                              const std::vector<double>& angles_deg) {
  Laminate laminate;
  for (double angle : angles_deg) laminate.plies.push_back(Ply{material, ply_thickness, angle});
  return laminate;
}

// The same with the angles first and an optional reference-surface offset (mm).
inline Laminate stack(const Material& material, const std::vector<double>& angles_deg,
                      double ply_thickness, double reference_offset = 0.0) {
  Laminate laminate = make_laminate(material, ply_thickness, angles_deg);
  laminate.reference_offset = reference_offset;
  return laminate;
}

// Lay-up notation helpers: [a/b]2S = a b a b | b a b a.
inline std::vector<double> repeat(const std::vector<double>& angles, int times) {
  std::vector<double> out;
  for (int i = 0; i < times; ++i) out.insert(out.end(), angles.begin(), angles.end());
  return out;
}
inline std::vector<double> symmetric(const std::vector<double>& half) {
  std::vector<double> out = half;
  out.insert(out.end(), half.rbegin(), half.rend());
  return out;
}

// Largest absolute entry, the scale for relative matrix comparisons.
template <typename M>
double max_abs(const M& m) {
  return m.cwiseAbs().maxCoeff();
}

// Reduced stiffness Q-bar of vam.md 10.1 (plane stress from E1, E2, nu12, G12, then the textbook
// rotation), in Yu order [11, 12, 22]; independent of the 3-D stiffness path of the code.
inline Matrix3d clt_reduced_stiffness(const EngineeringConstants& c, double angle_deg) {
  const double nu21 = c.nu12 * c.E2 / c.E1;
  const double d = 1.0 - c.nu12 * nu21;
  const double Q11 = c.E1 / d, Q22 = c.E2 / d, Q12 = c.nu12 * c.E2 / d, Q66 = c.G12;
  const double t = angle_deg * std::acos(-1.0) / 180.0;
  const double cs = std::cos(t), sn = std::sin(t);
  const double c2 = cs * cs, s2 = sn * sn, c4 = c2 * c2, s4 = s2 * s2;
  const double q11 = Q11 * c4 + 2 * (Q12 + 2 * Q66) * s2 * c2 + Q22 * s4;
  const double q22 = Q11 * s4 + 2 * (Q12 + 2 * Q66) * s2 * c2 + Q22 * c4;
  const double q12 = (Q11 + Q22 - 4 * Q66) * s2 * c2 + Q12 * (s4 + c4);
  const double q66 = (Q11 + Q22 - 2 * Q12 - 2 * Q66) * s2 * c2 + Q66 * (s4 + c4);
  const double q16 = (Q11 - Q12 - 2 * Q66) * sn * c2 * cs + (Q12 - Q22 + 2 * Q66) * s2 * sn * cs;
  const double q26 = (Q11 - Q12 - 2 * Q66) * s2 * sn * cs + (Q12 - Q22 + 2 * Q66) * sn * c2 * cs;
  Matrix3d Q;
  Q << q11, q16, q12, q16, q66, q26, q12, q26, q22;
  return Q;
}

// CLT [[A, B], [B, D]] about the laminate's reference surface (vam.md 10.1), Yu ordering.
inline Matrix6d textbook_clt_abd(const Laminate& laminate) {
  const std::vector<double> z = laminate.interfaces();
  Matrix6d abd = Matrix6d::Zero();
  for (size_t k = 0; k < laminate.plies.size(); ++k) {
    const Ply& ply = laminate.plies[k];
    const Matrix3d Q = clt_reduced_stiffness(ply.material.constants(), ply.angle_deg);
    const double a = z[k] - laminate.reference_offset, b = z[k + 1] - laminate.reference_offset;
    abd.topLeftCorner<3, 3>() += Q * (b - a);
    abd.topRightCorner<3, 3>() += Q * (b * b - a * a) / 2.0;
    abd.bottomRightCorner<3, 3>() += Q * (b * b * b - a * a * a) / 3.0;
  }
  abd.bottomLeftCorner<3, 3>() = abd.topRightCorner<3, 3>().transpose();
  return abd;
}

// Scales curvature rows/columns by sqrt(12)/h ("balanced strains", vam.md 6.3) so that membrane
// and bending entries of a 6 x 6 stiffness can be compared in one relative norm.
inline Matrix6d balanced(const Matrix6d& A, double h) {
  Vector6d t = Vector6d::Ones();
  t.tail<3>().setConstant(std::sqrt(12.0) / h);
  return t.asDiagonal() * A * t.asDiagonal();
}

}  // namespace si::testing
