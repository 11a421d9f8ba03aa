// The elastic face's kernel (contact/face_influence.hpp) against independent references:
//  * the J0 transform with algebraic tails (contact/hankel_j0.hpp) against closed forms:
//    e^-x -> (1 + rho^2)^-1/2 (Lipschitz) and -(x^2 + 4)^-1/2 -> -I0(rho) K0(rho) (G&R 6.552.1),
//    whose tail t1 = -1, t3 = 2 it must take in closed form, and the disc moment against
//    int rho (1 + rho^2)^-1/2 = (1 + b^2)^1/2 - 1;
//  * the Reissner-Mindlin compliance against the isotropic plate's 1 / (D k^3) + 1 / (G k);
//  * the kShell kernel: its series against its transfer-matrix values, its limits (kappa -> -1 at
//    long waves, where the two plates agree and the Poisson term is removed; t1 / x at short
//    ones, t1 from the shear stiffness);
//  * C(r) against a direct truncated Hankel integral of the kernel (no tail subtraction, no
//    table), and the disc coefficient against the average of C(r) over the disc.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/anisotropic_local_law.hpp"
#include "contact/face_influence.hpp"
#include "contact/hankel_j0.hpp"
#include "contact/reissner_mindlin_compliance.hpp"
#include "core/constants.hpp"
#include "io/case_file.hpp"
#include "section/gauss_legendre.hpp"

namespace si {
namespace {

TEST(HankelJ0, DecayingFunctionWithoutTail_Lipschitz) {
  const HankelJ0 t([](double x) { return std::exp(-x); }, 0, 0, 10);
  for (double rho : {0.001, 0.003, 0.1, 0.5, 1.0, 2.7, 6.0, 10.0})
    EXPECT_NEAR(t(rho), 1 / std::sqrt(1 + rho * rho), 2e-9) << rho;
  for (double b : {0.0, 0.01, 0.5, 3.0, 10.0})
    EXPECT_NEAR(t.moment(b), std::sqrt(1 + b * b) - 1, 2e-9 * (1 + b * b)) << b;
}

TEST(HankelJ0, AlgebraicTail_TakenInClosedForm) {
  // -(x^2 + 4)^-1/2 = -1/x + 2/x^3 - ...: t1 = -1, t3 = 2.
  const HankelJ0 t([](double x) { return -1 / std::sqrt(x * x + 4); }, -1, 2, 8);
  for (double rho : {0.002, 0.01, 0.2, 1.0, 3.3, 8.0}) {
    const double exact = -std::cyl_bessel_i(0.0, rho) * std::cyl_bessel_k(0.0, rho);
    EXPECT_NEAR(t(rho), exact, 1e-8 * (1 + std::abs(exact))) << rho;
  }
  // The disc moment of the logarithm at 0: int_0^b rho I0 K0 d rho = (b^2/2) (I0 K0 + I1 K1)(b)
  // (differentiate, with I1' = I0 - I1/rho, K1' = -K0 - K1/rho; rho^2 I1 K1 -> 0 at 0).
  for (double b : {0.05, 0.3, 2.0}) {
    const double m = -b * b / 2 *
                     (std::cyl_bessel_i(0.0, b) * std::cyl_bessel_k(0.0, b) +
                      std::cyl_bessel_i(1.0, b) * std::cyl_bessel_k(1.0, b));
    EXPECT_NEAR(t.moment(b), m, 1e-8 * std::abs(m)) << b;
  }
}

TEST(ReissnerMindlinCompliance, IsotropicPlate_BendingPlusShear) {
  const double E = 70000, nu = 0.3, h = 3.8, Gs = 5.0 / 6.0 * E / (2 * (1 + nu)) * h;
  const double D = E * h * h * h / (12 * (1 - nu * nu));
  Matrix3d Dm;
  Dm << D, 0, nu * D, 0, (1 - nu) / 2 * D, 0, nu * D, 0, D;
  const Matrix2d G = Matrix2d::Identity() * Gs;
  for (double k : {0.01, 0.3, 2.0, 50.0})
    for (double phi : {0.0, 0.7}) {
      const double exact = 1 / (D * k * k * k) + 1 / (Gs * k);
      EXPECT_NEAR(reissner_mindlin_compliance(Dm, G, phi, k), exact, 1e-12 * exact) << k;
    }
}

// The paper's cap [0/90]2S: the kernel of its elastic face (the section's own D and G).
std::shared_ptr<const SupportKernel> cross_ply_kernel() {
  const CaseFile c = parse_case_file(
      "material: paper-carbon-epoxy\n"
      "laminate: {layup: \"[0/90]2S\", ply_thickness: 0.475 mm}\n"
      "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n",
      "cap.yaml");
  const LocalContactLaw law =
      anisotropic_local_law(c.laminate, {LocalSupport::kShell, LocalPlies::kResolved, 10.98, 0.0});
  EXPECT_EQ(law.kind, LocalLawKind::kElasticFace);
  return law.face;
}

TEST(FaceInfluenceKernel, SeriesMatchesTransferMatricesAndLimits) {
  const std::shared_ptr<const SupportKernel> kernel = cross_ply_kernel();
  const SupportKernel& k = *kernel;
  for (double x : {0.05, 0.3, 1.0, 2.5, 7.0, 30.0, 150.0})
    EXPECT_NEAR(k.kappa(x), k.kappa_direct(x), 1e-5) << x;
  // Long waves: the two plates agree once the long-wave term L / x is removed, C(k) / H_inf -> 0
  // (at x = 0.2, the last transfer-matrix value before the linear model, and at 0.5).
  EXPECT_NEAR(k.kappa_direct(0.2), -1, 1e-2);
  EXPECT_NEAR(k.kappa_direct(0.5), -1, 5e-2);
  EXPECT_GT(k.kappa_direct(0.5), -1);  // the face is more compliant than the shell: C > 0
  // Short waves: kappa ~ t1 / x, t1 = -h <1 / e.G.e> / H_inf.
  const KappaTail tail = shell_kappa_tail(k);
  const Matrix2d& G = k.spec().shear_stiffness;  // [0/90]2S: G12 = 0, so <1 / e.G.e> in closed
  EXPECT_NEAR(G(0, 1), 0, 1e-9 * G(0, 0));       // form is 1 / sqrt(G11 G22)
  EXPECT_NEAR(tail.t1, -3.8 / std::sqrt(G(0, 0) * G(1, 1)) / k.far_compliance(),
              1e-3 * std::abs(tail.t1));
  EXPECT_NEAR(k.kappa_direct(300.0) * 300, tail.t1 + tail.t3 / (300.0 * 300), 1e-6);
}

// C(r) = (H_inf / 2 pi) [1/r + (1/h) int_0^X kappa(x) J0(x r / h) dx] by plain Gauss panels to
// X = 4000 (the truncation ~|t1| (2 / pi rho)^1/2 X^-1/2 / (rho X) ... below 1e-5 here), against
// the table with its tails in closed form.
TEST(FaceInfluence, PointCoefficientMatchesDirectIntegralAndDiscIsItsAverage) {
  const std::shared_ptr<const SupportKernel> kernel = cross_ply_kernel();
  const FaceInfluence face(kernel, 12.0);
  const double h = kernel->thickness(), H = kernel->far_compliance();
  const GaussRule g = gauss_legendre(8);
  for (double r : {0.25, 0.6, 1.5, 4.0, 10.0}) {
    const double rho = r / h, X = 4000, panel = std::min(0.25, 1 / rho);
    double s = 0;
    for (double a = 0; a < X; a += panel)
      for (std::size_t i = 0; i < g.points.size(); ++i) {
        const double x = a + panel * (g.points[i] + 1) / 2;
        s += panel / 2 * g.weights[i] * kernel->kappa(x) * std::cyl_bessel_j(0.0, x * rho);
      }
    const double direct = H / (2 * kPi) * (1 / r + s / h);
    EXPECT_NEAR(face.point(r), direct, 1e-4 * H / (2 * kPi * r)) << r;
  }
  // The disc's centre: (2 / b^2) int_0^b r C(r) dr by midpoints in r (C ~ 1/r: r C is smooth).
  for (double b : {0.1, 0.3, 0.8}) {
    double m = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
      const double r = (i + 0.5) / n * b;
      m += r * face.point(r) * b / n;
    }
    EXPECT_NEAR(face.disc(b), 2 / (b * b) * m, 1e-5 * face.disc(b)) << b;
  }
}

}  // namespace
}  // namespace si
