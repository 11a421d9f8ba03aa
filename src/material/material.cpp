#include "material/material.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "core/error.hpp"

namespace si {
namespace {

std::string num(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

void require_positive(double value, const char* key) {
  if (!(value > 0.0) || !std::isfinite(value))
    throw_input(std::string(key) + " must be positive and finite (got " + num(value) + " MPa)",
                Where{"", key, num(value) + " MPa", 0});
}

// |nu_ij| < sqrt(E_i/E_j) is necessary for a positive-definite compliance (Lempriere 1968).
void require_poisson_bound(double nu, double Ei, double Ej, const char* key, const char* ratio) {
  const double bound = std::sqrt(Ei / Ej);
  if (!std::isfinite(nu) || std::abs(nu) >= bound) {
    throw_input(std::string(key) + " = " + num(nu) + " is out of range: |" + key +
                    "| must be < sqrt(" + ratio + ") = " + num(bound) +
                    " for a positive-definite compliance",
                Where{"", key, num(nu), 0});
  }
}

}  // namespace

Material::Material(std::string name, const EngineeringConstants& c, bool isotropic)
    : name_(std::move(name)), c_(c), isotropic_(isotropic) {}

Material Material::orthotropic(std::string name, const EngineeringConstants& c) {
  require_positive(c.E1, "E1");
  require_positive(c.E2, "E2");
  require_positive(c.E3, "E3");
  require_positive(c.G12, "G12");
  require_positive(c.G13, "G13");
  require_positive(c.G23, "G23");
  require_poisson_bound(c.nu12, c.E1, c.E2, "nu12", "E1/E2");
  require_poisson_bound(c.nu13, c.E1, c.E3, "nu13", "E1/E3");
  require_poisson_bound(c.nu23, c.E2, c.E3, "nu23", "E2/E3");
  const double nu21 = c.nu12 * c.E2 / c.E1;
  const double nu31 = c.nu13 * c.E3 / c.E1;
  const double nu32 = c.nu23 * c.E3 / c.E2;
  const double delta =
      1.0 - c.nu12 * nu21 - c.nu23 * nu32 - c.nu13 * nu31 - 2.0 * nu21 * nu32 * c.nu13;
  if (!(delta > 0.0)) {
    throw_input(
        "the ply compliance matrix is not positive definite: 1 - nu12 nu21 - nu23 nu32 - "
        "nu13 nu31 - 2 nu21 nu32 nu13 = " +
            num(delta) + " <= 0 (check nu12, nu13, nu23)",
        Where{"", "nu12, nu13, nu23", num(c.nu12) + ", " + num(c.nu13) + ", " + num(c.nu23), 0});
  }
  return Material(std::move(name), c, false);
}

Material Material::isotropic(std::string name, double E, double nu) {
  require_positive(E, "E");
  if (!std::isfinite(nu) || !(nu > -1.0 && nu < 0.5)) {
    throw_input("nu = " + num(nu) + " is out of range: an isotropic solid needs -1 < nu < 0.5",
                Where{"", "nu", num(nu), 0});
  }
  const double G = E / (2.0 * (1.0 + nu));
  return Material(std::move(name), EngineeringConstants{E, E, E, G, G, G, nu, nu, nu}, true);
}

Material Material::with_failure_properties(const PlyStrengths& strengths,
                                           const FractureToughness& toughness) const {
  validate(strengths);
  validate(toughness);
  Material out = *this;
  out.strengths_ = strengths;
  out.toughness_ = toughness;
  return out;
}

Material Material::renamed(std::string name) const {
  Material out = *this;
  out.name_ = std::move(name);
  return out;
}

Matrix6d Material::compliance() const {
  const auto& c = c_;
  Matrix6d S = Matrix6d::Zero();
  S(0, 0) = 1.0 / c.E1;
  S(1, 1) = 1.0 / c.E2;
  S(2, 2) = 1.0 / c.E3;
  S(0, 1) = S(1, 0) = -c.nu12 / c.E1;
  S(0, 2) = S(2, 0) = -c.nu13 / c.E1;
  S(1, 2) = S(2, 1) = -c.nu23 / c.E2;
  S(3, 3) = 1.0 / c.G23;
  S(4, 4) = 1.0 / c.G13;
  S(5, 5) = 1.0 / c.G12;
  return S;
}

Matrix6d Material::stiffness() const {
  Matrix6d C = compliance().inverse();
  return 0.5 * (C + C.transpose());
}

}  // namespace si
