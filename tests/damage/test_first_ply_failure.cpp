// First-ply failure of laminates under uniform in-plane loads and under bending: the code path
// (VAM section -> 3-D recovery -> material axes -> criterion -> through-thickness maximum; the
// index is linear in the load, so the FPF load is the unit load over the largest index) against
// classical lamination theory worked by hand in the test: the plane-stress reduced stiffness, the
// closed-form [0/90]s ABD and its inverse, ply stresses at the ply faces, and the 2-D forms the
// criteria take when sigma33 = tau13 = tau23 = 0 (Jones 1999, sections 2.9 and 4.3; Hashin 1980
// eqs 20-23 with s33 = s13 = s23 = 0; Tsai-Wu with F12 = -sqrt(F11 F22)/2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../section/laminate_fixtures.hpp"
#include "damage/through_thickness_failure.hpp"
#include "material/material_library.hpp"
#include "section/through_thickness_recovery.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

// Plane ply stress in material axes per unit load, and the load factor to onset of each criterion
// in its 2-D form, by hand.
struct PlaneStress {
  double s1, s2, s12;
};

double smallest_positive_root(double a, double b) {  // a N^2 + b N = 1, a >= 0
  if (a == 0) return b > 0 ? 1 / b : INFINITY;
  return (-b + std::sqrt(b * b + 4 * a)) / (2 * a);
}

double max_stress_load(const PlaneStress& s, const Strengths& k) {
  const double r1 = s.s1 > 0 ? k.X_T / s.s1 : s.s1 < 0 ? -k.X_C / s.s1 : INFINITY;
  const double r2 = s.s2 > 0 ? k.Y_T / s.s2 : s.s2 < 0 ? -k.Y_C / s.s2 : INFINITY;
  const double r6 = s.s12 != 0 ? k.S_12 / std::abs(s.s12) : INFINITY;
  return std::min({r1, r2, r6});
}

double hashin_load(const PlaneStress& s, const Strengths& k) {
  const double shear = (s.s12 / k.S_12) * (s.s12 / k.S_12);
  const double fibre = s.s1 > 0 ? smallest_positive_root((s.s1 / k.X_T) * (s.s1 / k.X_T) + shear, 0)
                       : s.s1 < 0 ? k.X_C / -s.s1
                                  : INFINITY;
  double matrix;
  if (s.s2 >= 0) {
    matrix = smallest_positive_root((s.s2 / k.Y_T) * (s.s2 / k.Y_T) + shear, 0);
  } else {  // (s2/(2 S_23))^2 + [(Y_C/(2 S_23))^2 - 1] s2/Y_C + (s12/S_12)^2 = 1
    const double r = k.Y_C / (2 * k.S_23);
    matrix = smallest_positive_root((s.s2 / (2 * k.S_23)) * (s.s2 / (2 * k.S_23)) + shear,
                                    (r * r - 1) * s.s2 / k.Y_C);
  }
  return std::min(fibre, matrix);
}

double tsai_wu_load(const PlaneStress& s, const Strengths& k) {
  const double F1 = 1 / k.X_T - 1 / k.X_C, F2 = 1 / k.Y_T - 1 / k.Y_C;
  const double F11 = 1 / (k.X_T * k.X_C), F22 = 1 / (k.Y_T * k.Y_C), F66 = 1 / (k.S_12 * k.S_12);
  const double F12 = -0.5 * std::sqrt(F11 * F22);
  return smallest_positive_root(
      F11 * s.s1 * s.s1 + F22 * s.s2 * s.s2 + F66 * s.s12 * s.s12 + 2 * F12 * s.s1 * s.s2,
      F1 * s.s1 + F2 * s.s2);
}

// Textbook rotation of a plate-axis plane stress [sxx, syy, txy] into the ply axes.
PlaneStress to_ply_axes(double sxx, double syy, double txy, double angle_deg) {
  const double t = angle_deg * std::acos(-1.0) / 180, c = std::cos(t), s = std::sin(t);
  return {c * c * sxx + s * s * syy + 2 * s * c * txy, s * s * sxx + c * c * syy - 2 * s * c * txy,
          -s * c * sxx + s * c * syy + (c * c - s * s) * txy};
}

// The FPF load factor of each criterion along the code path: unit load in, 1 / max index out.
std::vector<double> code_path_fpf(const Laminate& laminate, const Vector6d& resultants) {
  const VamSection section = analyze_vam(laminate);
  PlateState state;
  state.R = section.A_R.inverse() * resultants;
  const ThroughThicknessFailure failure(
      laminate, {Criterion::kMaxStress, Criterion::kHashin, Criterion::kTsaiWu});
  std::vector<double> out;
  for (const CriterionFailure& c : failure.evaluate(recover_through_thickness(section, state, 3)))
    out.push_back(1 / c.governing.index.index);
  return out;
}

// The smallest load factor over the given ply points, per criterion.
std::vector<double> hand_fpf(const std::vector<PlaneStress>& points, const Strengths& k) {
  std::vector<double> out(3, INFINITY);
  for (const PlaneStress& s : points) {
    out[0] = std::min(out[0], max_stress_load(s, k));
    out[1] = std::min(out[1], hashin_load(s, k));
    out[2] = std::min(out[2], tsai_wu_load(s, k));
  }
  return out;
}

Strengths as4_strengths() {
  return strengths_for(Criterion::kMaxStress, library_material("as4-3501-6"));
}

// Plane-stress reduced stiffness of AS4/3501-6 (E1 126, E2 11, G12 6.6 GPa, nu12 0.28).
struct ReducedStiffness {
  double Q11, Q22, Q12, Q66;
};
ReducedStiffness as4_reduced_stiffness() {
  const double E1 = 126000, E2 = 11000, nu12 = 0.28, G12 = 6600;
  const double d = 1 - nu12 * nu12 * E2 / E1;
  return {E1 / d, E2 / d, nu12 * E2 / d, G12};
}

constexpr double kPly = 0.125;  // mm

// [0/90]s under N_x = 1 N/mm: A11 = A22 = (Q11 + Q22) h/2, A12 = Q12 h, strains from the 2 x 2
// inverse, one stress state per ply orientation.
TEST(FirstPlyFailure, CrossPlyUnderInPlaneTensionMatchesClt) {
  const ReducedStiffness q = as4_reduced_stiffness();
  const double h = 4 * kPly;
  const double A11 = (q.Q11 + q.Q22) * h / 2, A12 = q.Q12 * h;
  const double det = A11 * A11 - A12 * A12;
  const double ex = A11 / det, ey = -A12 / det;
  const PlaneStress zero{q.Q11 * ex + q.Q12 * ey, q.Q12 * ex + q.Q22 * ey, 0};
  const PlaneStress ninety{q.Q11 * ey + q.Q12 * ex, q.Q12 * ey + q.Q22 * ex, 0};
  const std::vector<double> expected = hand_fpf({zero, ninety}, as4_strengths());

  Vector6d N = Vector6d::Zero();
  N(0) = 1;
  const std::vector<double> got = code_path_fpf(
      testing::make_laminate(library_material("as4-3501-6"), kPly, {0, 90, 90, 0}), N);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i] / expected[i], 1.0, 1e-10) << "criterion " << i;
  // Transverse cracking of the 90 deg plies governs: N_x = Y_T / sigma2(90).
  EXPECT_NEAR(got[0], 48 / ninety.s2, 1e-9 * got[0]);
  std::printf(
      "[0/90]s AS4/3501-6, N_x at first-ply failure: max stress %.2f, Hashin %.2f, "
      "Tsai-Wu %.2f N/mm\n",
      got[0], got[1], got[2]);
}

// [0/90]s under M_x = 1 N mm/mm: D11 = (2/3)[Q11((h/2)^3 - (h/4)^3) + Q22 (h/4)^3], D22 with Q11
// and Q22 exchanged, D12 = Q12 h^3/12; ply stresses z (Q kappa) at every ply face.
TEST(FirstPlyFailure, CrossPlyUnderBendingMatchesClt) {
  const ReducedStiffness q = as4_reduced_stiffness();
  const double h = 4 * kPly, zo = h / 2, zi = h / 4;
  const double D11 = 2.0 / 3 * (q.Q11 * (zo * zo * zo - zi * zi * zi) + q.Q22 * zi * zi * zi);
  const double D22 = 2.0 / 3 * (q.Q22 * (zo * zo * zo - zi * zi * zi) + q.Q11 * zi * zi * zi);
  const double D12 = q.Q12 * h * h * h / 12;
  const double det = D11 * D22 - D12 * D12;
  const double kx = D22 / det, ky = -D12 / det;
  std::vector<PlaneStress> points;
  for (double z : {-zo, -zi, zi, zo})  // 0 deg plies
    points.push_back({z * (q.Q11 * kx + q.Q12 * ky), z * (q.Q12 * kx + q.Q22 * ky), 0});
  for (double z : {-zi, zi})  // 90 deg plies
    points.push_back({z * (q.Q11 * ky + q.Q12 * kx), z * (q.Q12 * ky + q.Q22 * kx), 0});
  const std::vector<double> expected = hand_fpf(points, as4_strengths());

  Vector6d M = Vector6d::Zero();
  M(3) = 1;
  const std::vector<double> got = code_path_fpf(
      testing::make_laminate(library_material("as4-3501-6"), kPly, {0, 90, 90, 0}), M);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i] / expected[i], 1.0, 1e-10) << "criterion " << i;
  std::printf(
      "[0/90]s AS4/3501-6, M_x at first-ply failure: max stress %.3f, Hashin %.3f, "
      "Tsai-Wu %.3f N mm/mm\n",
      got[0], got[1], got[2]);
}

// Quasi-isotropic [0/45/-45/90]s of IM7/8552 under combined N_x, N_xy and M_y: the textbook ABD
// (laminate_fixtures.hpp) inverted, ply stresses Q-bar (eps + z kappa) at every ply face, rotated
// by the textbook formula.
TEST(FirstPlyFailure, QuasiIsotropicUnderCombinedLoadsMatchesClt) {
  const Material im7 = library_material("im7-8552");
  const std::vector<double> angles{0, 45, -45, 90, 90, -45, 45, 0};
  const Laminate laminate = testing::make_laminate(im7, kPly, angles);
  Vector6d load;
  load << 1, 0.5, 0, 0, 0, -0.02;  // N_x, N_xy, N_y, M_x, M_xy, M_y (Yu order)
  const Vector6d strains = testing::textbook_clt_abd(laminate).inverse() * load;
  const std::vector<double> z = laminate.interfaces();
  std::vector<PlaneStress> points;
  for (size_t k = 0; k < angles.size(); ++k) {
    const Matrix3d Q = testing::clt_reduced_stiffness(im7.constants(), angles[k]);
    for (double x3 : {z[k], 0.5 * (z[k] + z[k + 1]), z[k + 1]}) {
      const Vector3d s = Q * (strains.head<3>() + x3 * strains.tail<3>());  // [xx, xy, yy]
      points.push_back(to_ply_axes(s(0), s(2), s(1), angles[k]));
    }
  }
  const std::vector<double> expected = hand_fpf(points, strengths_for(Criterion::kMaxStress, im7));
  const std::vector<double> got = code_path_fpf(laminate, load);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i] / expected[i], 1.0, 1e-10) << "criterion " << i;
}

}  // namespace
}  // namespace si
