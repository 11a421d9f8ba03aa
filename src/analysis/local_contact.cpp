#include "analysis/local_contact.hpp"

#include <cmath>

#include "contact/anisotropic_local_law.hpp"
#include "core/error.hpp"
#include "section/vam_section.hpp"

namespace si {

namespace {

// Young's modulus and Poisson ratio of an elastic indenter (its 1-direction constants; an
// indenter material is isotropic in practice); E = 0 for a rigid one.
void indenter_constants(const IndentationCase& c, double& E, double& nu) {
  E = 0, nu = 0;
  if (!c.indenter.material) return;
  E = c.indenter.material->constants().E1;
  nu = c.indenter.material->constants().nu12;
}

}  // namespace

LocalContactLaw local_contact_law(const IndentationCase& c) {
  const LocalContactModel m = c.contact.local;
  if (m == LocalContactModel::kNone) return {};
  if (m == LocalContactModel::kVam) {
    const double compliance = analyze_vam(c.laminate).c_L(0, 0);
    if (!(compliance > 0))
      throw_input("the section's face compliance c_L++ (local law vam) is not positive",
                  Where{c.file, "contact.local", "", 0});
    return {LocalLawKind::kThinLayer, 0.0, compliance, 0.0, nullptr, nullptr};
  }
  // The case-file reader refuses other shapes, naming the key (io/case_file.cpp).
  SI_REQUIRE(c.indenter.shape == IndenterShape::kSphere,
             "a Hertz-type local law needs a spherical indenter");
  const EngineeringConstants& top = c.laminate.plies.back().material.constants();
  double Ei = 0, nui = 0;
  indenter_constants(c, Ei, nui);
  const double Ri = c.indenter.radius;
  if (m == LocalContactModel::kYangSun) return yang_sun_law(Ri, Ei, nui, top.E3);
  const double R =
      c.shell.type == ShellType::kSphericalCap ? 1 / (1 / Ri + 1 / c.shell.radius) : Ri;
  if (m == LocalContactModel::kAnisotropic) {
    const double indenter = Ei > 0 ? 2 * (1 - nui * nui) / Ei : 0.0;
    return anisotropic_local_law(c.laminate,
                                 {c.contact.local_support, c.contact.local_plies, R, indenter});
  }
  return hertz_law(R, hertz_modulus(Ei, nui, top.E3, top.nu23));
}

LocalContactLaw face_pressure_law(const IndentationCase& c) {
  const LocalContactLaw own = local_contact_law(c);
  if (own.kind == LocalLawKind::kPowerLaw) return own;
  if (c.indenter.shape != IndenterShape::kSphere) return {};
  IndentationCase anisotropic = c;
  anisotropic.contact.local = LocalContactModel::kAnisotropic;
  anisotropic.contact.local_support = LocalSupport::kHalfSpace;
  anisotropic.contact.local_plies = LocalPlies::kHomogenised;
  return local_contact_law(anisotropic);
}

}  // namespace si
