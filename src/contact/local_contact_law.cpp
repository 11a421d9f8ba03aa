#include "contact/local_contact_law.hpp"

#include <cmath>

#include "core/error.hpp"

namespace si {

double LocalContactLaw::force(double alpha) const {
  if (layer) return layer->force(alpha);
  return std::copysign(k * std::pow(std::abs(alpha), 1.5), alpha);
}

double LocalContactLaw::stiffness(double alpha) const {
  if (layer) return layer->stiffness(alpha);
  return 1.5 * k * std::sqrt(std::abs(alpha));
}

double LocalContactLaw::energy(double alpha) const {
  if (layer) return layer->energy(alpha);
  return 0.4 * k * std::pow(std::abs(alpha), 2.5);
}

double LocalContactLaw::approach(double force) const {
  if (layer) return layer->approach(force);
  return std::copysign(std::pow(std::abs(force) / k, 2.0 / 3.0), force);
}

DentValue LocalContactLaw::dent(double r, double alpha) const {
  return dent_profile(alpha).at(r);
}

DentProfile LocalContactLaw::dent_profile(double alpha) const {
  DentProfile p;
  p.alpha = alpha;
  p.radius = radius;
  if (layer) p.layer = layer->dent_at(alpha);
  return p;
}

DentValue DentProfile::at(double r) const {
  if (layer) return layer->at(r);
  if (radius > 0) return hertz_dent(r, alpha, radius);
  return {alpha, 1.0};
}

namespace {

// The indenter's compliance term (1 - nu^2)/E; zero for a rigid indenter (E = 0).
double indenter_compliance(double E, double nu) {
  return E > 0 ? (1 - nu * nu) / E : 0.0;
}

}  // namespace

double hertz_modulus(double indenter_E, double indenter_nu, double shell_E, double shell_nu) {
  SI_REQUIRE(shell_E > 0, "hertz_modulus: the shell's modulus must be positive");
  return 1 / (indenter_compliance(indenter_E, indenter_nu) + (1 - shell_nu * shell_nu) / shell_E);
}

LocalContactLaw hertz_law(double sphere_radius, double modulus) {
  SI_REQUIRE(sphere_radius > 0 && modulus > 0, "hertz_law: radius and modulus must be positive");
  return {LocalLawKind::kPowerLaw,
          4.0 / 3.0 * modulus * std::sqrt(sphere_radius),
          0.0,
          sphere_radius,
          nullptr,
          nullptr};
}

LocalContactLaw layer_law(std::shared_ptr<const LayerContactLaw> law) {
  SI_REQUIRE(law != nullptr, "layer_law: no law");
  LocalContactLaw l = hertz_law(law->radius(), law->modulus());
  l.layer = std::move(law);
  return l;
}

LocalContactLaw yang_sun_law(double sphere_radius, double indenter_E, double indenter_nu,
                             double transverse_E) {
  SI_REQUIRE(sphere_radius > 0 && transverse_E > 0,
             "yang_sun_law: radius and transverse modulus must be positive");
  const double k = 4.0 / 3.0 * std::sqrt(sphere_radius) /
                   (indenter_compliance(indenter_E, indenter_nu) + 1 / transverse_E);
  return {LocalLawKind::kPowerLaw, k, 0.0, sphere_radius, nullptr, nullptr};
}

}  // namespace si
