// The local contact law of a case (`contact.local`, docs/case-file.md; the laws in
// contact/local_contact_law.hpp, the choices in docs/theory/local-indentation.md):
//  * hertz: F = (4/3) E* R^0.5 alpha^1.5 with 1/E* = (1 - nu_i^2)/E_i + (1 - nu_23^2)/E_3, the
//    laminate taken as an isotropic half-space with the top ply's transverse modulus E_3 and
//    transverse Poisson ratio nu_23 (for an isotropic ply: E and nu, Hertz exactly), and
//    1/R = 1/R_i + 1/R_cap for a spherical cap (two spheres), R = R_i otherwise;
//  * yang_sun: F = k alpha^1.5, k = (4/3) R_i^0.5 / [(1 - nu_i^2)/E_i + 1/E_3] (Yang & Sun 1982,
//    point-loads.md 4.4; their E_2 is the ply's transverse modulus, E_3 here);
//  * vam: the thin-layer law alpha_i = c_L++ p_i of the section (vam.md 7.3-7.4);
//  * anisotropic: the laminate's own 3-D stiffness under the sphere
//    (contact/anisotropic_local_law.hpp; contact.local_support, contact.local_plies), the
//    relative radius R as for hertz.
// A rigid indenter (no indenter.material) has no compliance term. hertz and yang_sun carry
// Hertz's dent profile (hertz_dent.hpp) with the radius of their own Hertz form: the relative
// radius R for hertz (the sphere on the cap's curvature, so the dented face conforms to the
// sphere inside the patch), R_i for yang_sun (a law for flat laminates: on a cap the patch keeps
// the cap's own curvature); anisotropic carries its own law's dent. All three need a sphere, whose
// profile alone is defined (the case-file reader refuses other shapes).
#pragma once

#include "analysis/indentation_case.hpp"
#include "contact/local_contact_law.hpp"

namespace si {

LocalContactLaw local_contact_law(const IndentationCase& c);

// The law that sizes the contacted face's resolved (Hertzian) pressure in the stress recovery
// (analysis/damage_probe.hpp, docs/theory/failure.md 7): the case's own power law if it has one,
// else, for a sphere, the laminate's anisotropic half-space (homogenised upper half, the relative
// radius R as above; the law whose approach matches a resolved 3-D model best,
// local-indentation.md 6.7); other indenters: none (the nodal pressure).
LocalContactLaw face_pressure_law(const IndentationCase& c);

}  // namespace si
