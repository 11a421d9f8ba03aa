// The local dent of Hertz contact: the surface displacement of an elastic half-space (both
// bodies' displacements summed) under a sphere of relative radius R pressed to the approach
// alpha, as a function of the distance r from the contact's axis (Johnson, Contact Mechanics,
// 1985, eqs 3.42a-b with the Hertz pressure p0 = 2 a E* / (pi R) of section 4.2; E* cancels):
//     a = (R alpha)^0.5                                          the patch radius
//     u(r) = alpha - r^2 / (2R)                                  r <= a (conforms to the sphere)
//     u(r) = [(2a^2 - r^2) asin(a/r) + a (r^2 - a^2)^0.5] / (pi R)   r > a
// u is C^1 in r and in alpha (continuous value and slope at r = a) and tends to the Boussinesq
// point-load field 4 a^3 / (3 pi R r) = F / (pi E* r) far away. Its rate
//     du/dalpha = 1 (r <= a),  (2/pi) asin(a/r) (r > a)
// is continuous too; the second derivative is unbounded at r = a and at alpha = 0.
// Negative alpha (Newton iterates): the odd extension u(r; alpha) = -u(r; |alpha|), as for the
// law F = k sgn(alpha) |alpha|^1.5, keeps u and its rate continuous at alpha = 0. At alpha = 0
// the point r = 0 counts as inside the patch (rate 1). Units: mm.
#pragma once

namespace si {

struct DentValue {
  double u = 0;     // mm
  double rate = 0;  // du/dalpha
};

DentValue hertz_dent(double r, double alpha, double radius);

}  // namespace si
