// The indentation of an anisotropic half-space (contact/anisotropic_half_space.hpp) against
// independent references (docs/verification.md, "Anisotropic local indentation"):
//  * isotropic: H = 2 (1 - nu^2)/E and both moduli E/(1 - nu^2) (Hertz);
//  * transversely isotropic with the axis normal to the face: the closed form
//        M = 2 [ (C11 C33 - C13^2) / C11 / (1/C44 + 2 / ((C11 C33)^0.5 + C13)) ]^0.5
//    (Delafargue & Ulm 2004, Int. J. Solids Struct. 41:7351, eq. 13, from Elliott 1948 and
//    Hanson's solution), to 1e-8 for three materials from mildly to strongly anisotropic;
//  * the Barnett-Lothe compliance equals the transfer-matrix compliance of a thick layer
//    (layer_compliance.hpp, a different method) for an orthotropic ply at any direction;
//  * Willis' ellipse: the real-space surface displacement under its Hertzian pressure, integrated
//    directly from the point-force Green's function w(theta)/r (w(theta) = H(theta + pi/2)/(2 pi)),
//    is the sphere's profile: equal curvatures in every direction, quadratic, and the force-
//    approach relation gives E_W;
//  * four-fold symmetry makes the contact circular (Willis = Vlassak & Nix), and rotating the
//    material rotates the ellipse and leaves the moduli unchanged.
#include <gtest/gtest.h>

#include <cmath>

#include "../verification_record.hpp"
#include "contact/anisotropic_half_space.hpp"
#include "contact/layer_compliance.hpp"
#include "core/constants.hpp"
#include "material/material.hpp"
#include "material/ply_rotation.hpp"
#include "section/homogenised_stiffness.hpp"

namespace si {
namespace {

const char* const kTable = "anisotropic-indentation";

Material paper_ply() {
  EngineeringConstants c;
  c.E1 = 130000, c.E2 = c.E3 = 10000, c.G12 = 6000, c.G13 = 3000, c.G23 = 6000;
  c.nu12 = 0.3, c.nu13 = 0.5, c.nu23 = 0.3;
  return Material::orthotropic("paper", c);
}

// Transversely isotropic about x3: E in the plane, E3 along the axis.
Material transversely_isotropic(double E, double nu, double E3, double nu13, double G13) {
  EngineeringConstants c;
  c.E1 = c.E2 = E, c.E3 = E3, c.nu12 = nu, c.nu13 = c.nu23 = nu13;
  c.G12 = E / (2 * (1 + nu)), c.G13 = c.G23 = G13;
  return Material::orthotropic("ti", c);
}

double delafargue_ulm(const Matrix6d& C) {
  const double C11 = C(0, 0), C13 = C(0, 2), C33 = C(2, 2), C44 = C(3, 3);
  return 2 *
         std::sqrt((C11 * C33 - C13 * C13) / C11 / (1 / C44 + 2 / (std::sqrt(C11 * C33) + C13)));
}

TEST(AnisotropicHalfSpace, Isotropic_HertzModulus) {
  const double E = 70000, nu = 0.3;
  const Matrix6d C = Material::isotropic("iso", E, nu).stiffness();
  for (double phi : {0.0, 0.4, 1.3}) {
    EXPECT_NEAR(half_space_normal_compliance(C, phi), 2 * (1 - nu * nu) / E, 1e-13 / E);
  }
  const HalfSpaceIndentation h = half_space_indentation(C);
  EXPECT_NEAR(h.vlassak_nix, E / (1 - nu * nu), 1e-10 * E);
  EXPECT_NEAR(h.willis, E / (1 - nu * nu), 1e-10 * E);
  EXPECT_NEAR(h.aspect, 1.0, 1e-12);
  test::record_verification(kTable, "isotropic half-space: Willis modulus / (E / (1 - nu^2))",
                            E / (1 - nu * nu), h.willis, 1e-10, "Hertz (Johnson 1985, 4.2)");
}

TEST(AnisotropicHalfSpace, TransverselyIsotropic_DelafargueUlmClosedForm_1e8) {
  struct Case {
    const char* name;
    Material m;
  };
  const Case cases[] = {
      {"E/E3 = 4", transversely_isotropic(40000, 0.3, 10000, 0.25, 5000)},
      {"E/E3 = 20, G13 = E3/5", transversely_isotropic(200000, 0.25, 10000, 0.3, 2000)},
      {"E/E3 = 0.1 (stiff axis)", transversely_isotropic(5000, 0.2, 50000, 0.05, 10000)},
  };
  for (const Case& c : cases) {
    const Matrix6d C = c.m.stiffness();
    const double reference = delafargue_ulm(C);
    const HalfSpaceIndentation h = half_space_indentation(C);
    EXPECT_NEAR(h.vlassak_nix / reference, 1.0, 1e-8) << c.name;
    EXPECT_NEAR(h.willis / reference, 1.0, 1e-8) << c.name;
    EXPECT_NEAR(h.aspect, 1.0, 1e-10) << c.name;
    test::record_verification(kTable, std::string("transversely isotropic half-space, ") + c.name,
                              reference, h.willis, 1e-8,
                              "Delafargue & Ulm 2004, eq. 13 (closed form)");
  }
}

TEST(AnisotropicHalfSpace, BarnettLothe_EqualsTransferMatrixOfAThickLayer) {
  const Matrix6d C = paper_ply().stiffness();
  for (double phi : {0.0, 0.5, kPi / 2, 2.6}) {
    const double h = half_space_normal_compliance(C, phi);
    // k h = 60: the base's influence is e^-(60 Im p) below roundoff.
    EXPECT_NEAR(layer_normal_compliance({{C, 1.0}}, LayerBase::kBonded, phi, 60.0), h, 1e-9 * h);
    EXPECT_NEAR(layer_normal_compliance({{C, 1.0}}, LayerBase::kFrictionless, phi, 60.0), h,
                1e-9 * h);
  }
  // The trapezoidal rule has converged at 64 points.
  EXPECT_NEAR(half_space_normal_compliance(C, 0.3, 32), half_space_normal_compliance(C, 0.3, 128),
              1e-13 * half_space_normal_compliance(C, 0.3));
}

// The face displacement at x0 under p0 (1 - x^T Q x)^0.5 on its ellipse, integrated in real space
// with the point-force Green's function w(theta) / r: in polar coordinates about x0 the 1/r
// cancels, u(x0) = int_0^2pi w(theta) L(theta) dtheta, L the pressure's integral along the ray
// (closed form: the square root of a quadratic).
double real_space_displacement(const Matrix6d& C, const Matrix2d& Q, double p0,
                               const Vector2d& x0) {
  constexpr int kRays = 720;
  double u = 0;
  for (int j = 0; j < kRays; ++j) {
    const double theta = 2 * kPi * j / kRays;
    const Vector2d e(std::cos(theta), std::sin(theta));
    // 1 - (x0 + s e)^T Q (x0 + s e) = c (s_plus - s)(s - s_minus)
    const double c = e.dot(Q * e), b = e.dot(Q * x0), a0 = 1 - x0.dot(Q * x0);
    const double disc = std::sqrt(b * b + c * a0);
    const double s_plus = (-b + disc) / c, s_minus = (-b - disc) / c;
    const double m = (s_plus + s_minus) / 2, d = (s_plus - s_minus) / 2;
    const double phi0 = std::asin(std::clamp(-m / d, -1.0, 1.0));
    const double L = p0 * std::sqrt(c) * d * d * (kPi / 4 - phi0 / 2 - std::sin(2 * phi0) / 4);
    const double w = half_space_normal_compliance(C, theta + kPi / 2) / (2 * kPi);
    u += w * L * 2 * kPi / kRays;
  }
  return u;
}

TEST(AnisotropicHalfSpace, WillisEllipse_RealSpaceDisplacementIsTheSpheresProfile) {
  const Matrix6d C = paper_ply().stiffness();  // [0] ply: fibres along x1
  const HalfSpaceIndentation h = half_space_indentation(C);
  EXPECT_LT(h.aspect, 0.99);  // a measurably elliptical contact
  // The ellipse: semi-axes c / aspect^0.5 along the major axis, c aspect^0.5 across, c = 1 mm.
  const double t = h.major_axis_deg * kPi / 180;
  Matrix2d Rot;
  Rot << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
  const Matrix2d A = Rot * Vector2d(1 / h.aspect, h.aspect).asDiagonal() * Rot.transpose();
  const Matrix2d Q = A.inverse();  // c = 1
  const double p0 = 100.0, d = 0.3;
  const double u0 = real_space_displacement(C, Q, p0, Vector2d::Zero());
  double curvature[3];
  const Vector2d dirs[3] = {Vector2d(1, 0), Vector2d(0, 1), Vector2d(1, 1).normalized()};
  for (int k = 0; k < 3; ++k)
    curvature[k] = (u0 - real_space_displacement(C, Q, p0, d * dirs[k])) / (d * d);
  EXPECT_NEAR(curvature[1] / curvature[0], 1.0, 1e-6);
  EXPECT_NEAR(curvature[2] / curvature[0], 1.0, 1e-6);
  // Quadratic: twice the distance, four times the drop.
  EXPECT_NEAR((u0 - real_space_displacement(C, Q, p0, 2 * d * dirs[0])) / (4 * d * d), curvature[0],
              1e-6 * curvature[0]);
  // u = alpha - r^2 / (2R): R = 1 / (2 curvature), F = (2/3) pi c^2 p0 = (4/3) E R^0.5 u0^1.5.
  const double R = 1 / (2 * curvature[0]), F = 2.0 / 3.0 * kPi * p0;
  const double E = 0.75 * F / (std::sqrt(R) * std::pow(u0, 1.5));
  EXPECT_NEAR(E / h.willis, 1.0, 1e-6);
  test::record_verification(kTable, "[0] paper ply: Willis modulus vs real-space Green's function",
                            E, h.willis, 1e-6, "direct integration of w(theta)/r over the ellipse");
}

TEST(AnisotropicHalfSpace, FourFoldSymmetry_CircularContactAndRotationCovariance) {
  const Matrix6d ply = paper_ply().stiffness();
  const Matrix6d cross = homogenised_stiffness(
      {{ply, 1.0}, {rotate_stiffness_voigt(ply, 90), 1.0}});  // [0/90] homogenised
  const HalfSpaceIndentation h = half_space_indentation(cross);
  EXPECT_NEAR(h.aspect, 1.0, 1e-10);
  EXPECT_NEAR(h.willis / h.vlassak_nix, 1.0, 1e-10);
  const HalfSpaceIndentation h0 = half_space_indentation(ply);
  const HalfSpaceIndentation h30 = half_space_indentation(rotate_stiffness_voigt(ply, 30));
  EXPECT_NEAR(h30.willis / h0.willis, 1.0, 1e-9);
  EXPECT_NEAR(h30.aspect, h0.aspect, 1e-9);
  EXPECT_NEAR(std::remainder(h30.major_axis_deg - h0.major_axis_deg - 30, 180.0), 0.0, 1e-6);
}

TEST(AnisotropicHalfSpace, ElasticIndenter_CompliancesAdd) {
  const Matrix6d C = transversely_isotropic(40000, 0.3, 10000, 0.25, 5000).stiffness();
  const double Hi = 2 * (1 - 0.09) / 210000;  // steel
  const double M = half_space_indentation(C).willis;
  EXPECT_NEAR(half_space_indentation(C, Hi).willis, 2 / (2 / M + Hi), 1e-9 * M);
}

}  // namespace
}  // namespace si
