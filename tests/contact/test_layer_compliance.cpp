// The transfer-matrix surface compliance of layers (contact/layer_compliance.hpp) against
// independent references (docs/verification.md, "Anisotropic local indentation"):
//  * an isotropic layer on a rigid base, the classical closed forms in x = k h, kappa = 3 - 4 nu
//    (plane strain, Airy function (A + B k z) cosh k z + (C + D k z) sinh k z; e.g. Chen & Engel
//    1972, Int. J. Solids Struct. 8:1257, and the thin-film indentation literature):
//        bonded:        H / H_inf = (2 kappa sinh 2x - 4x) / (2 kappa cosh 2x + 1 + kappa^2 + 4x^2)
//        frictionless:  H / H_inf = (cosh 2x - 1) / (sinh 2x + 2x),   H_inf = 2 (1 - nu^2) / E;
//    their limits are h / (lambda + 2 mu) (a bonded thin layer in uniaxial strain) and the
//    half-space;
//  * a layer cut into sublayers of the same material is the same layer;
//  * the free plate: at long waves the top face rises against the mid-plane by Kirchhoff's
//    Poisson term, x (H_top - H_mid) -> -c2 with c2 = 3 nu (1 + nu) / (2 E) for an isotropic
//    plate (plate bending with sigma_33 = 0: e33 = nu/(1 - nu) z kappa); at short waves the top
//    face is the top ply's half-space (Barnett-Lothe, anisotropic_half_space.hpp) and the
//    mid-plane at rest.
#include <gtest/gtest.h>

#include <cmath>

#include "../verification_record.hpp"
#include "contact/anisotropic_half_space.hpp"
#include "contact/layer_compliance.hpp"
#include "material/material.hpp"
#include "material/ply_rotation.hpp"

namespace si {
namespace {

const char* const kTable = "anisotropic-indentation";
constexpr double kE = 70000, kNu = 0.3;

std::vector<LayerStiffness> isotropic_layer(double h) {
  return {{Material::isotropic("iso", kE, kNu).stiffness(), h}};
}

double bonded_closed_form(double x) {
  const double k = 3 - 4 * kNu;
  return (2 * k * std::sinh(2 * x) - 4 * x) / (2 * k * std::cosh(2 * x) + 1 + k * k + 4 * x * x);
}

double frictionless_closed_form(double x) {
  return (std::cosh(2 * x) - 1) / (std::sinh(2 * x) + 2 * x);
}

TEST(LayerCompliance, IsotropicLayerOnRigidBase_ClosedForms_1e10) {
  const double H_inf = 2 * (1 - kNu * kNu) / kE, h = 1.9;
  for (double x : {0.01, 0.3, 1.0, 3.0, 10.0}) {
    for (double phi : {0.0, 0.9}) {  // isotropic: any direction
      const double bonded =
          layer_normal_compliance(isotropic_layer(h), LayerBase::kBonded, phi, x / h) / H_inf;
      const double frictionless =
          layer_normal_compliance(isotropic_layer(h), LayerBase::kFrictionless, phi, x / h) / H_inf;
      EXPECT_NEAR(bonded / bonded_closed_form(x), 1.0, 1e-10) << x;
      EXPECT_NEAR(frictionless / frictionless_closed_form(x), 1.0, 1e-10) << x;
    }
  }
  const double x = 1.0;
  test::record_verification(
      kTable, "isotropic layer bonded to a rigid base, H / H_inf at k h = 1", bonded_closed_form(x),
      layer_normal_compliance(isotropic_layer(h), LayerBase::kBonded, 0, x / h) / H_inf, 1e-10,
      "closed form (plane strain, Airy function)");
  test::record_verification(
      kTable, "isotropic layer on a frictionless rigid base, H / H_inf at k h = 1",
      frictionless_closed_form(x),
      layer_normal_compliance(isotropic_layer(h), LayerBase::kFrictionless, 0, x / h) / H_inf,
      1e-10, "closed form (plane strain, Airy function)");
  // Thin bonded layer: uniaxial strain, H = k h / (lambda + 2 mu).
  const double lambda_2mu = kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)), k = 1e-3 / h;
  EXPECT_NEAR(layer_normal_compliance(isotropic_layer(h), LayerBase::kBonded, 0, k),
              k * h / lambda_2mu, 1e-5 * k * h / lambda_2mu);
}

TEST(LayerCompliance, SublayersOfOneMaterial_AreOneLayer) {
  EngineeringConstants c;
  c.E1 = 130000, c.E2 = c.E3 = 10000, c.G12 = 6000, c.G13 = 3000, c.G23 = 6000;
  c.nu12 = 0.3, c.nu13 = 0.5, c.nu23 = 0.3;
  const Matrix6d C = rotate_stiffness_voigt(Material::orthotropic("ply", c).stiffness(), 30);
  const std::vector<LayerStiffness> one{{C, 1.2}}, three{{C, 0.1}, {C, 0.7}, {C, 0.4}};
  for (double k : {0.2, 2.0, 9.0}) {
    const double h1 = layer_normal_compliance(one, LayerBase::kBonded, 0.7, k);
    EXPECT_NEAR(layer_normal_compliance(three, LayerBase::kBonded, 0.7, k), h1, 1e-11 * h1);
    const PlateFaceCompliance p1 = plate_face_compliance(one, 0.7, k);
    const PlateFaceCompliance p3 = plate_face_compliance(three, 0.7, k);
    EXPECT_NEAR(p3.top, p1.top, 1e-10 * std::abs(p1.top));
    EXPECT_NEAR(p3.mid, p1.mid, 1e-10 * std::abs(p1.mid));
    EXPECT_NEAR(p3.average, p1.average, 1e-10 * std::abs(p1.average));
  }
}

TEST(LayerCompliance, FreeIsotropicPlate_KirchhoffPoissonTermAtLongWaves) {
  const double t = 3.8, c2 = 1.5 * kNu * (1 + kNu) / kE;
  // x = 3e-3: the O(x^2) remainder ~1e-5, the cancellation of the 1/x^3 bending terms ~1e-7.
  const double x = 3e-3;
  const PlateFaceCompliance p = plate_face_compliance(isotropic_layer(t), 0.2, x / t);
  EXPECT_NEAR(x * (p.top - p.mid) / -c2, 1.0, 1e-4);
  test::record_verification(kTable, "free isotropic plate, k t = 3e-3: -(k t)(H_top - H_mid) / c2",
                            1.0, x * (p.top - p.mid) / -c2, 1e-4,
                            "Kirchhoff bending with sigma_33 = 0 (Poisson thickness change)");
  // Plate bending dominates: the top face and the mid-plane move together, ~ 1 / (D k^3).
  EXPECT_NEAR(p.mid / p.top, 1.0, 1e-5);
}

TEST(LayerCompliance, FreePlateOfPlies_ShortWavesSeeTheTopPlysHalfSpace) {
  EngineeringConstants c;
  c.E1 = 130000, c.E2 = c.E3 = 10000, c.G12 = 6000, c.G13 = 3000, c.G23 = 6000;
  c.nu12 = 0.3, c.nu13 = 0.5, c.nu23 = 0.3;
  const Matrix6d ply = Material::orthotropic("ply", c).stiffness();
  std::vector<LayerStiffness> layers;
  for (double angle : {0, 90, 0, 90, 90, 0, 90, 0})
    layers.push_back({rotate_stiffness_voigt(ply, angle), 0.475});
  for (double phi : {0.0, 1.0}) {
    // k t = 800, k t_ply = 100: the plies below the top one are out of sight (e^-(2 k t_ply Im p)).
    const PlateFaceCompliance p = plate_face_compliance(layers, phi, 800 / 3.8);
    const double h = half_space_normal_compliance(ply, phi);  // the top ply is at 0 deg
    EXPECT_NEAR(p.top / h, 1.0, 1e-8);
    EXPECT_LT(std::abs(p.mid), 1e-12 * h);
  }
}

}  // namespace
}  // namespace si
