// The finite-thickness local contact law: the sphere-on-support contact solution
// (contact/sphere_on_layer.hpp) and its tables (contact/layer_contact_law.hpp), against
// independent references (docs/verification.md, "Anisotropic local indentation"):
//  * Hertz as the contact radius vanishes against the thickness (A = 1, B = 4/3, P = 2);
//  * the incremental stiffness of a smooth indenter is the flat punch's at the current contact
//    radius (Shield 1967; the theorem behind the method of dimensionality reduction): dF/dalpha
//    from the sphere's solutions at neighbouring radii against the punch's own solution;
//  * a thin bonded layer is a Winkler foundation of modulus (lambda + 2 mu) / h: A -> 1/2 and
//    B / lambda -> (pi / 4) (lambda + 2 mu) / M as a / h grows (approached like 1 + O(h / a));
//  * the outer dent's support term by the Abel identity (sphere_on_layer.hpp) against the Hankel
//    integral with Bessel's J0 (a different route to the same integral);
//  * the tables against direct solutions between their nodes, and the law's force, stiffness,
//    energy, inverse and dent against each other (finite differences, continuity at the edge).
#include <gtest/gtest.h>

#include <cmath>

#include "../verification_record.hpp"
#include "contact/layer_contact_law.hpp"
#include "contact/sphere_on_layer.hpp"
#include "contact/support_kernel.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "material/material.hpp"
#include "material/ply_rotation.hpp"

namespace si {
namespace {

const char* const kTable = "anisotropic-indentation";
constexpr double kE = 70000, kNu = 0.3;

SupportSpec isotropic_layer(LocalSupport support, double h) {
  SupportSpec s;
  s.support = support;
  s.layers = {{Material::isotropic("iso", kE, kNu).stiffness(), h}};
  return s;
}

// The paper's [0/90]2S as a free plate (resolved plies), with a Reissner-Mindlin shear stiffness
// of the order of the section's (5/6 t G13).
SupportSpec paper_plate() {
  EngineeringConstants c;
  c.E1 = 130000, c.E2 = c.E3 = 10000, c.G12 = 6000, c.G13 = 3000, c.G23 = 6000;
  c.nu12 = 0.3, c.nu13 = 0.5, c.nu23 = 0.3;
  const Matrix6d ply = Material::orthotropic("ply", c).stiffness();
  SupportSpec s;
  s.support = LocalSupport::kPlate;
  for (double angle : {0, 90, 0, 90, 90, 0, 90, 0})
    s.layers.push_back({rotate_stiffness_voigt(ply, angle), 0.475});
  s.shear_stiffness = Matrix2d::Identity() * 5.0 / 6.0 * 3.8 * 4000;
  return s;
}

TEST(SphereOnLayer, SmallContactRadius_Hertz) {
  const SupportKernel kernel(isotropic_layer(LocalSupport::kBondedBase, 1.0), 2.0);
  const SphereOnLayer contact(kernel);
  const SphereOnLayerSolution s = contact.solve(1e-4);
  EXPECT_NEAR(s.approach, 1.0, 1e-3);
  EXPECT_NEAR(s.force, 4.0 / 3.0, 1e-3);
  EXPECT_NEAR(s.punch, 2.0, 1e-3);
}

TEST(SphereOnLayer, IncrementalStiffnessIsTheFlatPunchs_ShieldsTheorem) {
  const SupportKernel layer(isotropic_layer(LocalSupport::kBondedBase, 1.0), 4.0);
  const SupportKernel plate(paper_plate(), 4.0);
  for (const SupportKernel* kernel : {&layer, &plate}) {
    const SphereOnLayer contact(*kernel);
    const double a = 0.7, d = 1e-4;
    const SphereOnLayerSolution lo = contact.solve(a - d), hi = contact.solve(a + d);
    const double F_lo = lo.force * std::pow(a - d, 3), F_hi = hi.force * std::pow(a + d, 3);
    const double alpha_lo = lo.approach * (a - d) * (a - d);
    const double alpha_hi = hi.approach * (a + d) * (a + d);
    const double stiffness = (F_hi - F_lo) / (alpha_hi - alpha_lo);
    const double punch = contact.solve(a).punch * a;
    EXPECT_NEAR(stiffness / punch, 1.0, 1e-6);
    test::record_verification(kTable,
                              kernel == &layer
                                  ? "bonded isotropic layer, a/h = 0.7: dF/dalpha / flat punch"
                                  : "[0/90]2S plate, a/t = 0.7: dF/dalpha / flat punch",
                              1.0, stiffness / punch, 1e-6, "Shield 1967 (flat-punch theorem)");
  }
}

TEST(SphereOnLayer, ThinBondedLayer_TendsToTheWinklerFoundation) {
  const SupportKernel kernel(isotropic_layer(LocalSupport::kBondedBase, 1.0), 40.0);
  const SphereOnLayer contact(kernel, 160);
  const double M = kE / (1 - kNu * kNu), lambda_2mu = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu));
  const double winkler = kPi / 4 * lambda_2mu / M;
  const SphereOnLayerSolution s8 = contact.solve(8), s16 = contact.solve(16);
  // Richardson with the O(h/a) approach: 2 f(16) - f(8).
  const double B = 2 * s16.force / 16 - s8.force / 8, A = 2 * s16.approach - s8.approach;
  EXPECT_NEAR(A, 0.5, 0.01);
  EXPECT_NEAR(B / winkler, 1.0, 0.02);
  test::record_verification(kTable, "thin bonded isotropic layer: F R / (M a^3 (a/h)) extrapolated",
                            winkler, B, 0.02, "Winkler foundation (lambda + 2 mu) / h");
}

TEST(SphereOnLayer, OuterDent_AbelFormEqualsTheHankelIntegral) {
  const SupportKernel kernel(isotropic_layer(LocalSupport::kBondedBase, 1.0), 24.0);
  const SphereOnLayer contact(kernel);
  const double a = 0.8;
  const SphereOnLayerSolution s = contact.solve(a);
  const KernelQuadrature q = kernel.quadrature(40, 0.125);
  for (double r : {0.9, 1.5, 3.0}) {
    // The punch's profile: the outer_face's Abel form against 2 int_0^beta g1(r sin theta) dtheta
    // (the half-space's part, g1 between the nodes by Nystrom's interpolation) plus the support's
    // part as a Hankel integral with J0.
    const double beta = std::asin(a / r);
    const SphereOnLayer::OuterFace face = contact.outer_face(s, {a / r});
    double half_space = 0;
    for (int j = 0; j < 400; ++j) {  // midpoint rule: g1 is smooth
      const double theta = beta * (j + 0.5) / 400;
      half_space += 2 * beta / 400 * (1 / kPi - contact.applied_kernel(s, r * std::sin(theta))[0]);
    }
    double hankel = 0;
    for (std::size_t k = 0; k < q.x.size(); ++k) {
      double gbar = 0;
      for (Eigen::Index j = 0; j < s.t.size(); ++j)
        gbar += s.w[j] * s.g1[j] * std::cos(q.x[k] * s.t[j]);
      hankel += 2 * q.weight[k] * q.kappa[k] * gbar * std::cyl_bessel_j(0.0, q.x[k] * r);
    }
    EXPECT_NEAR(face.punch[0], half_space + hankel, 1e-6) << r;
  }
}

TEST(SphereOnLayer, OuterDentRateIsTheFlatPunchsProfile_ShieldsTheorem) {
  // The same theorem for the face outside the contact: du/dalpha at fixed r is the displacement
  // of the unit flat punch of the current radius (the dent's rate in the gaps).
  const SupportKernel kernel(isotropic_layer(LocalSupport::kFrictionlessBase, 1.0), 24.0);
  const SphereOnLayer contact(kernel);
  const double a = 0.5, d = 1e-5;
  const SphereOnLayerSolution s0 = contact.solve(a), lo = contact.solve(a - d),
                              hi = contact.solve(a + d);
  for (double r : {0.65, 1.25}) {
    const double u_lo = contact.outer_face(lo, {(a - d) / r}).sphere[0] * (a - d) * (a - d);
    const double u_hi = contact.outer_face(hi, {(a + d) / r}).sphere[0] * (a + d) * (a + d);
    const double alpha_lo = lo.approach * (a - d) * (a - d);
    const double alpha_hi = hi.approach * (a + d) * (a + d);
    const double rate = contact.outer_face(s0, {a / r}).punch[0];
    EXPECT_NEAR((u_hi - u_lo) / (alpha_hi - alpha_lo), rate, 1e-7 * rate) << r;
  }
}

TEST(LayerContactLaw, TablesMatchDirectSolutionsBetweenTheirNodes) {
  const SupportSpec spec = paper_plate();
  const LayerContactLaw law(spec, 10.98);
  const SupportKernel kernel(spec, 8.0 + 16);
  const SphereOnLayer contact(kernel);
  for (double lambda : {0.037, 0.41, 1.13, 2.71}) {
    const SphereOnLayerSolution s = contact.solve(lambda);
    // Degree 32 in tau: the plate's lambda^3 log lambda terms leave a few 1e-6.
    EXPECT_NEAR(law.approach_ratio(lambda), s.approach, 3e-6 * s.approach) << lambda;
    EXPECT_NEAR(law.force_ratio(lambda), s.force, 3e-6 * s.force) << lambda;
    EXPECT_NEAR(law.punch_ratio(lambda), s.punch, 3e-6 * s.punch) << lambda;
    // The outer dent (units: h = M = R = 1 in the solution, R = 10.98 mm in the law).
    const double a = lambda * law.thickness(), alpha = s.approach * a * a / law.radius();
    for (double r_over_a : {1.2, 2.0, 4.0}) {
      const SphereOnLayer::OuterFace face = contact.outer_face(s, {1 / r_over_a});
      const DentValue d = law.dent(r_over_a * a, alpha);
      EXPECT_NEAR(d.u, face.sphere[0] * a * a / law.radius(), 3e-5 * alpha) << lambda;
      // The rate, the tables' derivative of u, is the flat punch's profile (Shield) to a few 1e-3.
      EXPECT_NEAR(d.rate, face.punch[0], 5e-3) << lambda;
    }
  }
}

TEST(LayerContactLaw, ForceStiffnessEnergyInverseAndDentAreConsistent) {
  const LayerContactLaw law(isotropic_layer(LocalSupport::kFrictionlessBase, 1.9), 10.98);
  for (double alpha : {0.003, 0.05, 0.2, 0.6}) {
    const double d = 1e-6 * alpha;
    const double F = law.force(alpha);
    EXPECT_NEAR((law.force(alpha + d) - law.force(alpha - d)) / (2 * d), law.stiffness(alpha),
                1e-6 * law.stiffness(alpha));
    EXPECT_NEAR((law.energy(alpha + d) - law.energy(alpha - d)) / (2 * d), F, 1e-6 * F);
    EXPECT_NEAR(law.approach(F), alpha, 1e-10 * alpha);
    EXPECT_NEAR(law.force(-alpha), -F, 1e-12 * F);
    // The dent: continuous with the patch at r = a, its rate the derivative of u in alpha.
    const double a = law.contact_radius(alpha);
    // At r = a (1 + e) the outer profile's variable (1 - a/r)^0.5 is e^0.5: its rate is
    // 1 - O(e^0.5), as the half-space's (2/pi) asin(a/r).
    const DentValue in = law.dent(a * (1 - 1e-14), alpha), out = law.dent(a * (1 + 1e-14), alpha);
    EXPECT_NEAR(out.u, in.u, 1e-9 * alpha);
    EXPECT_NEAR(out.rate, 1.0, 1e-6);
    // The rate is the derivative of u in alpha at fixed r (the Jacobian's dent rows).
    for (double r : {1.001 * a, 1.3 * a, 2.5 * a}) {
      const double fd = (law.dent(r, alpha + d).u - law.dent(r, alpha - d).u) / (2 * d);
      EXPECT_NEAR(law.dent(r, alpha).rate, fd, 1e-6 * std::max(fd, 1e-3)) << alpha << " " << r;
    }
  }
}

TEST(LayerContactLaw, SmallApproach_IsHertzWithTheHalfSpaceModulus) {
  const LayerContactLaw law(isotropic_layer(LocalSupport::kBondedBase, 1.9), 10.98);
  const double M = kE / (1 - kNu * kNu);
  EXPECT_NEAR(law.modulus(), M, 1e-9 * M);
  const double alpha = 1e-7;  // a / h ~ 5e-4
  EXPECT_NEAR(law.force(alpha) / (4.0 / 3.0 * M * std::sqrt(10.98) * std::pow(alpha, 1.5)), 1.0,
              2e-3);
  const DentValue d = law.dent(3 * std::sqrt(10.98 * alpha), alpha);
  const DentValue hertz = hertz_dent(3 * std::sqrt(10.98 * alpha), alpha, 10.98);
  EXPECT_NEAR(d.u / hertz.u, 1.0, 2e-3);
  EXPECT_NEAR(d.rate / hertz.rate, 1.0, 2e-3);
}

TEST(LayerContactLaw, BeyondTheTable_IsANumericalError) {
  const LayerContactLaw law(isotropic_layer(LocalSupport::kBondedBase, 1.0), 10.0, 2.0);
  EXPECT_THROW(law.force(50.0), Error);
}

}  // namespace
}  // namespace si
