#include "contact/anisotropic_local_law.hpp"

#include <memory>

#include "contact/anisotropic_half_space.hpp"
#include "core/error.hpp"
#include "section/homogenised_stiffness.hpp"
#include "section/vam_section.hpp"

namespace si {

LocalContactLaw anisotropic_local_law(const Laminate& laminate, const AnisotropicLawSpec& spec) {
  SI_REQUIRE(spec.sphere_radius > 0, "anisotropic_local_law: the radius must be positive");
  SI_REQUIRE(spec.indenter_compliance >= 0,
             "anisotropic_local_law: the indenter's compliance must not be negative");
  laminate.validate();
  const double h = laminate.thickness();
  const bool shell = spec.support == LocalSupport::kShell;
  const bool plate = spec.support == LocalSupport::kPlate || shell;
  const std::vector<LayerStiffness> plies = laminate_layers(laminate, plate ? -h / 2 : 0.0, h / 2);
  if (spec.support == LocalSupport::kHalfSpace) {
    const Matrix6d C =
        spec.plies == LocalPlies::kResolved ? plies.back().C : homogenised_stiffness(plies);
    return hertz_law(spec.sphere_radius,
                     half_space_indentation(C, spec.indenter_compliance).willis);
  }
  SupportSpec support;
  support.support = spec.support;
  support.indenter_compliance = spec.indenter_compliance;
  if (spec.plies == LocalPlies::kResolved || shell)
    support.layers = plies;
  else
    support.layers = {{homogenised_stiffness(plies), plate ? h : h / 2}};
  if (shell) {
    const VamSection v = analyze_vam(laminate);
    // D about the mid-surface (the plates' middle): A_R = T^T A_mid T (vam_section.hpp).
    const Matrix6d Ti = mid_surface_strain_map(v.reference_offset).inverse();
    support.shear_stiffness = v.G;
    support.bending_stiffness = (Ti.transpose() * v.A_R * Ti).block<3, 3>(3, 3);
    LocalContactLaw l;
    l.kind = LocalLawKind::kElasticFace;
    // The kernel's cosine transform (for the axisymmetric laws) is not used: a small range.
    l.face = std::make_shared<const SupportKernel>(support, 1.0);
    return l;
  }
  if (plate) support.shear_stiffness = analyze_vam(laminate).G;
  return layer_law(std::make_shared<const LayerContactLaw>(support, spec.sphere_radius));
}

}  // namespace si
