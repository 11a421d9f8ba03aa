// Hertz's dent profile (contact/hertz_dent.hpp) against an independent reference: the surface
// displacement of a half-space under the Hertz pressure p = p0 (1 - rho^2/a^2)^0.5, integrated
// numerically from Boussinesq's point-load solution u = p dA / (pi E* |x - y|) (Johnson 1985,
// eq 3.19 summed over both bodies), with Hertz's p0 = 3F / (2 pi a^2), a^3 = 3 F R / (4 E*) and
// approach alpha = a^2 / R (point-loads.md 4.3). Inside the patch the dented surface must conform
// to the sphere (Hertz's contact condition); the rate d u / d alpha is checked against central
// differences, and the profile's continuity at the patch edge and at alpha = 0.
#include "contact/hertz_dent.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../verification_record.hpp"
#include "core/constants.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

constexpr double kRadius = 12.7;    // mm, the sphere
constexpr double kModulus = 7e4;    // E*, MPa: cancels in the profile
constexpr double kApproach = 0.02;  // alpha, mm: a = 0.504 mm

// Boussinesq's integral of the Hertz pressure at distance r from the axis (r = 0 or r > a: the
// kernel 1/|x - y| is then regular in the disc's polar coordinates). rho = a sin(beta) removes
// the pressure's square-root edge (p rho d rho = p0 a^2 sin(beta) cos^2(beta) d beta), Gauss-
// Legendre in beta; the trapezoidal rule in the angle psi, spectrally accurate for a periodic
// analytic integrand (its convergence factor is rho / r <= a / r).
double boussinesq_displacement(double r, double alpha) {
  const double a = std::sqrt(kRadius * alpha);
  const double force = 4.0 / 3.0 * kModulus * std::sqrt(kRadius) * std::pow(alpha, 1.5);
  const double p0 = 3 * force / (2 * kPi * a * a);
  const GaussRule rule = gauss_legendre(80);
  const int n_psi = 800;
  double sum = 0;
  for (std::size_t g = 0; g < rule.points.size(); ++g) {
    const double beta = kPi / 4 * (rule.points[g] + 1), w_beta = kPi / 4 * rule.weights[g];
    const double rho = a * std::sin(beta);
    double ring = 0;  // integral over psi of 1 / |x - y|
    for (int k = 0; k < n_psi; ++k) {
      const double psi = 2 * kPi * k / n_psi;
      ring += 1 / std::sqrt(r * r + rho * rho - 2 * r * rho * std::cos(psi));
    }
    ring *= 2 * kPi / n_psi;
    sum += w_beta * p0 * a * a * std::sin(beta) * std::cos(beta) * std::cos(beta) * ring;
  }
  return sum / (kPi * kModulus);
}

TEST(HertzDent, CentreAndOutsideThePatch_BoussinesqIntegralOfTheHertzPressure) {
  const double a = std::sqrt(kRadius * kApproach);
  for (double ratio : {0.0, 1.2, 2.0, 5.0}) {
    const double r = ratio * a;
    const double reference = boussinesq_displacement(r, kApproach);
    const double u = hertz_dent(r, kApproach, kRadius).u;
    test::record_verification("local-indentation",
                              "Hertz dent u(r), r = " + std::to_string(ratio).substr(0, 3) +
                                  " a (a = 0.504 mm, alpha = 0.02 mm)",
                              reference, u, 1e-10,
                              "Boussinesq integral of the Hertz pressure (quadrature)");
    EXPECT_NEAR(u, reference, 1e-10 * reference) << "r/a = " << ratio;
  }
}

// Far away the dent is Boussinesq's point-load field F / (pi E* r); the next term of the
// expansion is (1/10) (a/r)^2 relative, 1e-7 at r = 1000 a.
TEST(HertzDent, FarField_BoussinesqPointLoad) {
  const double a = std::sqrt(kRadius * kApproach), r = 1000 * a;
  const double force = 4.0 / 3.0 * kModulus * std::sqrt(kRadius) * std::pow(kApproach, 1.5);
  const double reference = force / (kPi * kModulus * r);
  EXPECT_NEAR(hertz_dent(r, kApproach, kRadius).u, reference, 2e-7 * reference);
}

// Inside the patch the surface conforms to the sphere: u(r) + r^2 / (2R) = alpha.
TEST(HertzDent, InsideThePatch_ConformsToTheSphere) {
  const double a = std::sqrt(kRadius * kApproach);
  for (double ratio : {0.0, 0.3, 0.7, 1.0}) {
    const double r = ratio * a;
    const DentValue d = hertz_dent(r, kApproach, kRadius);
    EXPECT_NEAR(d.u + r * r / (2 * kRadius), kApproach, 1e-15);
    EXPECT_EQ(d.rate, 1.0);
  }
}

// C^1 across the patch edge r = a, in r and in alpha: value, slope -a/R and rate 1 from both
// sides (one-sided differences, O(step) accurate, with the step 1e-7 a).
TEST(HertzDent, ContinuouslyDifferentiableAcrossThePatchEdge) {
  const double a = std::sqrt(kRadius * kApproach), e = 1e-7 * a;
  const double inside = hertz_dent(a - e, kApproach, kRadius).u;
  const double edge = hertz_dent(a, kApproach, kRadius).u;
  const double outside = hertz_dent(a + e, kApproach, kRadius).u;
  EXPECT_NEAR((edge - inside) / e, -a / kRadius, 1e-6 * a / kRadius);
  EXPECT_NEAR((outside - edge) / e, -a / kRadius, 1e-3 * a / kRadius);  // sqrt-type edge
  EXPECT_NEAR(hertz_dent(a + e, kApproach, kRadius).rate, 1.0, 1e-3);
}

// d u / d alpha against central differences inside, near the edge and far outside the patch,
// for positive and negative alpha (the odd extension: u odd, rate even).
TEST(HertzDent, RateMatchesFiniteDifferencesAndIsEvenInAlpha) {
  const double a = std::sqrt(kRadius * kApproach), step = 1e-7;
  for (double ratio : {0.5, 1.5, 10.0})
    for (double sign : {1.0, -1.0}) {
      const double r = ratio * a, alpha = sign * kApproach;
      const double fd =
          (hertz_dent(r, alpha + step, kRadius).u - hertz_dent(r, alpha - step, kRadius).u) /
          (2 * step);
      const DentValue d = hertz_dent(r, alpha, kRadius);
      EXPECT_NEAR(d.rate, fd, 1e-6) << "r/a = " << ratio << ", alpha = " << alpha;
      EXPECT_EQ(d.u, -hertz_dent(r, -alpha, kRadius).u);
      EXPECT_EQ(d.rate, hertz_dent(r, -alpha, kRadius).rate);
    }
}

// At alpha = 0 the patch is the axis: r = 0 is inside (rate 1, the start's pivot), every other
// point has rate 0; the profile vanishes.
TEST(HertzDent, AtZeroApproach_TheAxisIsInsideThePatch) {
  EXPECT_EQ(hertz_dent(0.0, 0.0, kRadius).rate, 1.0);
  EXPECT_EQ(hertz_dent(0.0, 0.0, kRadius).u, 0.0);
  EXPECT_EQ(hertz_dent(0.5, 0.0, kRadius).rate, 0.0);
  EXPECT_EQ(hertz_dent(0.5, 0.0, kRadius).u, 0.0);
}

}  // namespace
}  // namespace si
