// Local (through-thickness) contact compliance in series with a shell (issue 7,
// docs/theory/local-indentation.md). A shell has no through-thickness compliance: its contact
// face moves with the mid-surface. The local law adds the approach alpha of the indenter towards
// the shell's contact face that the face's own flattening allows:
//  * kPowerLaw: one approach for the whole contact, F = k alpha^1.5 with F the total contact
//    force (whole shell). Hertz (point-loads.md 4.3): k = (4/3) E* R^0.5; Yang & Sun 1982
//    (point-loads.md 4.4): k = (4/3) R^0.5 / [(1 - nu_i^2)/E_i + 1/E_2]. Both are Hertz's law
//    in form, so the approach has Hertz's dent profile around the contact axis (hertz_dent.hpp)
//    with the law's radius R: what the face loses at distance r from the axis, dent(r, alpha).
//    A finite-thickness law (layer_contact_law.hpp: the anisotropic law on a base or as a plate)
//    is a kPowerLaw whose force, stiffness, energy and dent come from its tables instead: F(alpha)
//    is Hertz's at small alpha and stiffens as the contact radius grows against the thickness.
//  * kThinLayer: a per-node approach c p_i, p_i the node's contact pressure and c the section's
//    face compliance c_L++ (vam.md 7.3-7.4): linear, local to each node.
//  * kElasticFace: the face's approach at each node under every node's force, sum_j C_ij f_j,
//    from the laminate's 3-D solution less the shell's own plate (face_influence.hpp): linear,
//    non-local; no dent profile and no alpha (the influence coefficients are the dent).
// Units: mm, N, MPa.
#pragma once

#include <memory>
#include <optional>

#include "contact/hertz_dent.hpp"
#include "contact/layer_contact_law.hpp"

namespace si {

enum class LocalLawKind { kNone, kPowerLaw, kThinLayer, kElasticFace };

// A power law's dent at one approach alpha, for the many r of one Newton iterate (a
// finite-thickness law's per-alpha work, its contact radius and table slice, done once).
struct DentProfile {
  double alpha = 0;
  double radius = 0;  // Hertz's R; 0: the uniform approach alpha
  std::optional<LayerContactLaw::Dent> layer;
  DentValue at(double r) const;
};

struct LocalContactLaw {
  LocalLawKind kind = LocalLawKind::kNone;
  double k = 0;           // kPowerLaw: N/mm^1.5
  double compliance = 0;  // kThinLayer: mm/MPa
  // kPowerLaw: the radius R of the law's Hertz form k = (4/3) E R^0.5 (mm), the relative radius
  // of the dent profile; 0: no profile, the whole face approaches the indenter by alpha.
  double radius = 0;
  // kPowerLaw of finite thickness: the tabulated law; k and radius are then its small-alpha Hertz
  // form (4/3) M R^0.5 and R (for reports).
  std::shared_ptr<const LayerContactLaw> layer;
  // kElasticFace: the face's kernel (support kShell), from which the problem builds the
  // influence coefficients between its candidates (face_influence.hpp).
  std::shared_ptr<const SupportKernel> face;

  // kPowerLaw. F(alpha) = k sgn(alpha) |alpha|^1.5: the odd extension keeps Newton iterates with
  // alpha < 0 defined (a solution has alpha >= 0 since F >= 0). F is C^1 with F'(0) = 0.
  double force(double alpha) const;
  double stiffness(double alpha) const;  // dF/dalpha = 1.5 k |alpha|^0.5, N/mm
  double energy(double alpha) const;     // integral of F dalpha = (2/5) k |alpha|^2.5, N mm
  double approach(double force) const;   // inverse: (F/k)^(2/3), mm
  // kPowerLaw: the face's local displacement towards the shell at distance r (mm) from the
  // contact axis and its rate d/dalpha: hertz_dent(r, alpha, radius), or alpha and 1 without a
  // radius (a rigid approach of the whole face).
  DentValue dent(double r, double alpha) const;
  DentProfile dent_profile(double alpha) const;
};

// Rigid indenter: pass indenter_E = 0 (its compliance term is then zero).
// E* of Hertz: 1/E* = (1 - nu_i^2)/E_i + (1 - nu_s^2)/E_s (point-loads.md 4.3).
double hertz_modulus(double indenter_E, double indenter_nu, double shell_E, double shell_nu);
// Hertz's F = (4/3) E* R^0.5 alpha^1.5 (sphere of radius R on a half-space); dent radius R.
LocalContactLaw hertz_law(double sphere_radius, double modulus);
// The finite-thickness law as a kPowerLaw (the header).
LocalContactLaw layer_law(std::shared_ptr<const LayerContactLaw> law);
// Yang & Sun (1982), point-loads.md 4.4: k = (4/3) R^0.5 / [(1 - nu_i^2)/E_i + 1/E_2], E_2 the
// transverse modulus of the top ply; dent radius R (the law's own Hertz form).
LocalContactLaw yang_sun_law(double sphere_radius, double indenter_E, double indenter_nu,
                             double transverse_E);

}  // namespace si
