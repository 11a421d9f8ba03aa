// Verification of the VAM 3-D recovery (shared/docs/vam.md 8) against the equilibrium of the
// 2-D resultants, the face tractions (sign convention of vam.md 1), the textbook CLT ply stresses
// (vam.md 10.1) and the closed-form shear and normal stresses of a homogeneous plate.
#include "section/through_thickness_recovery.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "laminate_fixtures.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

using testing::clt_reduced_stiffness;
using testing::paper_material;
using testing::stack;

Laminate unsymmetric_laminate(double offset = 0.0) {
  return stack(paper_material(), {30, -30, 0, 90}, 0.475, offset);
}

Vector6d unit(int i) {
  return Vector6d::Unit(i);
}

// A generic 2-D state: every component of R, R_,1 and R_,2 non-zero.
PlateState generic_state(double t_top, double t_bottom) {
  PlateState state;
  state.R << 1e-3, -2e-4, 5e-4, 2e-4, -1e-4, 3e-4;
  state.dR[0] << 2e-5, 1e-5, -3e-5, 4e-5, 2e-5, -1e-5;
  state.dR[1] << -1e-5, 3e-5, 2e-5, -2e-5, 1e-5, 5e-5;
  state.t_top = t_top;
  state.t_bottom = t_bottom;
  return state;
}

// int_{-h/2}^{h/2} f(point) dx3 by Gauss-Legendre per ply; exact for the polynomial fields of a
// p = 4, one-element-per-ply section (degree <= 4 per ply).
template <typename F>
auto integrate_through_thickness(const VamSection& s, const PlateState& state, F f) {
  const GaussRule rule = gauss_legendre(6);
  const std::vector<double>& z = s.mesh.interfaces();
  using Value = decltype(f(recover_point(s, state, 0, z[0])));
  Value sum = Value::Zero();
  for (int k = 0; k + 1 < static_cast<int>(z.size()); ++k) {
    const double half = 0.5 * (z[k + 1] - z[k]);
    for (size_t g = 0; g < rule.points.size(); ++g) {
      const double x3 = z[k] + half * (1.0 + rule.points[g]);
      sum = sum + rule.weights[g] * half * f(recover_point(s, state, k, x3));
    }
  }
  return sum;
}

// vam.md 8: sigma13, sigma23 vanish on both faces and integrate to the shear resultants
// Q1 = M11,1 + M12,2 and Q2 = M12,1 + M22,2. Unit states from the in-plane equilibrium
// (N_,a = 0): R_,1 = A_R^-1 e_M11 gives Q = (1, 0); R_,2 = A_R^-1 e_M22 gives Q = (0, 1).
// Also with the reference surface on the bottom face (M about it has the same gradient when
// N_,a = 0), which exercises the conversion of the state to the mid-surface.
TEST(ThroughThicknessRecovery, Vam8_TransverseShearVanishesAtFacesAndIntegratesToQ) {
  for (double offset : {0.0, -0.95}) {
    const VamSection s = analyze_vam(unsymmetric_laminate(offset));
    const Matrix6d compliance = s.A_R.inverse();
    for (int a = 0; a < 2; ++a) {
      PlateState state = generic_state(-0.7, 0.2);
      state.dR[0].setZero();
      state.dR[1].setZero();
      state.dR[a] = compliance * unit(a == 0 ? 3 : 5);
      const double h = s.mesh.thickness();
      const RecoveredPoint bottom = recover_point(s, state, 0, -h / 2);
      const RecoveredPoint top = recover_point(s, state, s.mesh.plies() - 1, h / 2);
      const double tau = 1.0 / h;  // mean shear stress of a unit resultant
      for (int i : {3, 4}) {
        EXPECT_LT(std::abs(bottom.stress(i)), 1e-10 * tau) << "offset " << offset << " a " << a;
        EXPECT_LT(std::abs(top.stress(i)), 1e-10 * tau) << "offset " << offset << " a " << a;
      }
      const Vector2d Q = integrate_through_thickness(
          s, state, [](const RecoveredPoint& p) { return Vector2d(p.stress(3), p.stress(4)); });
      EXPECT_NEAR(Q(0), a == 0 ? 1.0 : 0.0, 1e-10) << "offset " << offset;
      EXPECT_NEAR(Q(1), a == 1 ? 1.0 : 0.0, 1e-10) << "offset " << offset;
    }
  }
}

// vam.md 8: sigma13 and sigma23 are continuous at ply interfaces (so is the warping, whose nodes
// are shared); the in-plane stresses jump there, as they must between plies of different angle.
TEST(ThroughThicknessRecovery, Vam8_TransverseStressesContinuousAtInterfaces) {
  const VamSection s = analyze_vam(unsymmetric_laminate());
  const PlateState state = generic_state(-0.7, 0.2);
  const std::vector<double>& z = s.mesh.interfaces();
  double shear_scale = 0;
  for (const RecoveredPoint& p : recover_through_thickness(s, state, 5))
    shear_scale = std::max(shear_scale, p.stress.segment<2>(3).cwiseAbs().maxCoeff());
  ASSERT_GT(shear_scale, 0.0);
  for (int k = 1; k + 1 < static_cast<int>(z.size()); ++k) {
    const RecoveredPoint below = recover_point(s, state, k - 1, z[k]);
    const RecoveredPoint above = recover_point(s, state, k, z[k]);
    EXPECT_LT((below.stress.segment<2>(3) - above.stress.segment<2>(3)).norm(), 1e-10 * shear_scale)
        << "interface " << k;
    EXPECT_NEAR(below.stress(5), above.stress(5), 1e-12) << "interface " << k;
    EXPECT_LT((below.warping - above.warping).norm(), 1e-14 * (1.0 + below.warping.norm()));
    EXPECT_GT((below.stress.head<3>() - above.stress.head<3>()).norm(), 1.0) << "interface " << k;
  }
}

// vam.md 1 and 8: sigma33(h/2) = t+ and sigma33(-h/2) = -t- (tractions along +x3; an indenter
// pressure p is t+ = -p), and the simple form is linear in between whatever the strains.
TEST(ThroughThicknessRecovery, Vam8_Sigma33EqualsFaceTractions) {
  const VamSection s = analyze_vam(unsymmetric_laminate());
  const double t_top = -2.5, t_bottom = 0.4;
  const PlateState state = generic_state(t_top, t_bottom);
  const double h = s.mesh.thickness();
  for (const RecoveredPoint& p : recover_through_thickness(s, state, 4)) {
    const double linear = -t_bottom + (t_top + t_bottom) * (p.x3 + h / 2) / h;
    EXPECT_NEAR(p.stress(5), linear, 1e-12 * std::abs(t_top)) << "x3 " << p.x3;
  }
  EXPECT_NEAR(recover_point(s, state, 3, h / 2).stress(5), t_top, 1e-12 * std::abs(t_top));
  EXPECT_NEAR(recover_point(s, state, 0, -h / 2).stress(5), -t_bottom, 1e-12 * std::abs(t_top));
}

// vam.md 8, recommended form: sigma33 = -t- - int (sigma13,1 + sigma23,2) reaches t+ on the top
// face exactly when the 2-D equilibrium M11,11 + 2 M12,12 + M22,22 + t+ + t- = 0 holds, and
// otherwise misses it by that residual. R_,11 = m11 A^-1 e_M11, R_,12 = m12 A^-1 e_M12,
// R_,22 = m22 A^-1 e_M22 give M11,11 = m11, M12,12 = m12, M22,22 = m22 with N_,ab = 0.
TEST(ThroughThicknessRecovery, Vam8_Sigma33ByEquilibriumMatchesTopTraction) {
  const VamSection s = analyze_vam(unsymmetric_laminate());
  const Matrix6d compliance = s.A_R.inverse();
  const double t_top = -2.5, t_bottom = 0.4, q = t_top + t_bottom;
  const double h = s.mesh.thickness();
  struct Case {
    double m11, m12, m22;
  };
  for (const Case& c : {Case{-q, 0, 0}, Case{-0.25 * q, -0.125 * q, -0.5 * q}, Case{1.0, 0.5, 2}}) {
    PlateState state = generic_state(t_top, t_bottom);
    state.d2R = std::array<Vector6d, 3>{c.m11 * compliance * unit(3), c.m12 * compliance * unit(4),
                                        c.m22 * compliance * unit(5)};
    const double residual = c.m11 + 2 * c.m12 + c.m22 + q;
    const RecoveredPoint top = recover_point(s, state, 3, h / 2);
    const RecoveredPoint bottom = recover_point(s, state, 0, -h / 2);
    ASSERT_TRUE(top.sigma33_equilibrium.has_value());
    EXPECT_NEAR(*top.sigma33_equilibrium, t_top - residual, 1e-10 * std::abs(q));
    EXPECT_NEAR(*bottom.sigma33_equilibrium, -t_bottom, 1e-14);
  }
  EXPECT_FALSE(recover_point(s, generic_state(t_top, t_bottom), 1, 0.0).sigma33_equilibrium);
}

// Homogeneous isotropic plate (E = 1, nu = 0.3, h = 1) under a unit shear resultant: the recovery
// gives the parabola sigma13 = 3/(2h) (1 - 4 x3^2/h^2), and with M11,11 = -q the equilibrium
// sigma33 = -t- + q (1/2 + 3 x3/(2h) - 2 x3^3/h^3) (integral of the parabola's gradient).
TEST(ThroughThicknessRecovery, Vam8_HomogeneousPlate_ParabolicShearAndCubicSigma33) {
  const double h = 1.0;
  const VamSection s = analyze_vam(stack(Material::isotropic("iso", 1.0, 0.3), {0}, h));
  const Matrix6d compliance = s.A_R.inverse();
  const double t_top = -0.6, t_bottom = 0.1, q = t_top + t_bottom;
  PlateState state;
  state.dR[0] = compliance * unit(3);
  state.t_top = t_top;
  state.t_bottom = t_bottom;
  state.d2R =
      std::array<Vector6d, 3>{-q * compliance * unit(3), Vector6d::Zero(), Vector6d::Zero()};
  for (const RecoveredPoint& p : recover_through_thickness(s, state, 9)) {
    const double x = p.x3;
    EXPECT_NEAR(p.stress(3), 1.5 / h * (1 - 4 * x * x / (h * h)), 1e-12) << "x3 " << x;
    EXPECT_NEAR(p.stress(4), 0.0, 1e-12);
    const double cubic = -t_bottom + q * (0.5 + 1.5 * x / h - 2 * x * x * x / (h * h * h));
    EXPECT_NEAR(*p.sigma33_equilibrium, cubic, 1e-12) << "x3 " << x;
  }
}

// vam.md 5.2 and 8: for a membrane/bending state without gradients or loads, the in-plane
// stresses are the CLT ply stresses Q-bar_k (eps + (x3 - e) kappa) of vam.md 10.1 and the
// transverse stresses vanish; also with the reference surface at e = -h/2.
TEST(ThroughThicknessRecovery, Vam8_InPlaneStressesEqualCltPlyStresses) {
  for (double offset : {0.0, -0.95}) {
    const Laminate laminate = unsymmetric_laminate(offset);
    const VamSection s = analyze_vam(laminate);
    PlateState state;
    state.R << 1e-3, -2e-4, 5e-4, 2e-4, -1e-4, 3e-4;
    const std::vector<RecoveredPoint> points = recover_through_thickness(s, state, 5);
    ASSERT_EQ(points.size(), 20u);
    double scale = 0;
    for (const RecoveredPoint& p : points) scale = std::max(scale, p.stress.norm());
    for (const RecoveredPoint& p : points) {
      const Ply& ply = laminate.plies[p.ply];
      const Matrix3d Q = clt_reduced_stiffness(ply.material.constants(), ply.angle_deg);
      const Vector3d clt = Q * (state.R.head<3>() + (p.x3 - offset) * state.R.tail<3>());
      EXPECT_LT((p.stress.head<3>() - clt).norm(), 1e-12 * scale) << "x3 " << p.x3;
      EXPECT_LT(p.stress.tail<3>().norm(), 1e-12 * scale) << "x3 " << p.x3;
    }
  }
}

// vam.md 2.1 and 8: the recovered warping has zero thickness average (the 2-D displacements
// are thickness averages), for a state with strains, gradients and tractions.
TEST(ThroughThicknessRecovery, Vam8_WarpingHasZeroThicknessAverage) {
  const VamSection s = analyze_vam(unsymmetric_laminate());
  const PlateState state = generic_state(-2.5, 0.4);
  const Vector3d mean = integrate_through_thickness(
      s, state, [](const RecoveredPoint& p) { return Vector3d(p.warping); });
  double scale = 0;
  for (const RecoveredPoint& p : recover_through_thickness(s, state, 5))
    scale = std::max(scale, p.warping.norm());
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(mean.norm(), 1e-12 * scale * s.mesh.thickness());
}

TEST(ThroughThicknessRecovery, RefusesPointsOutsideThePly) {
  const VamSection s = analyze_vam(unsymmetric_laminate());
  const PlateState state = generic_state(0, 0);
  for (auto [ply, x3] : {std::pair{0, 0.0}, {3, -0.95}, {4, 0.9}, {-1, 0.0}, {0, -0.96}}) {
    try {
      recover_point(s, state, ply, x3);
      ADD_FAILURE() << "accepted ply " << ply << " x3 " << x3;
    } catch (const Error& error) {
      EXPECT_EQ(error.kind(), ErrorKind::kInput);
    }
  }
  EXPECT_THROW(recover_through_thickness(s, state, 1), Error);
  const std::vector<RecoveredPoint> points = recover_through_thickness(s, state, 2);
  ASSERT_EQ(points.size(), 8u);
  EXPECT_DOUBLE_EQ(points.front().x3, -0.95);
  EXPECT_DOUBLE_EQ(points.back().x3, 0.95);
}

}  // namespace
}  // namespace si
