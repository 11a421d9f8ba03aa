// A local contact law of finite thickness: a rigid sphere of (relative) radius R pressed by the
// approach alpha into a support of thickness h (support_kernel.hpp), from the axisymmetric
// contact solution (sphere_on_layer.hpp) tabulated once over the contact radius a in [0, a_max]
// (docs/theory/local-indentation.md 6.5-6.6). With lambda = a / h and M = 2 / H_inf:
//     alpha = A(lambda) a^2 / R,   F = B(lambda) M a^3 / R,   dF/dalpha = P(lambda) M a,
// A, B, P Chebyshev series in tau = (lambda / lambda_max)^0.5 (Hertz: A = 1, B = 4/3, P = 2; a
// finite support: A falls towards 1/2, the thin-layer limit where the face stays at rest outside
// the patch and a^2 = 2 R alpha). The law is F(alpha) through a(alpha) (alpha increases with a);
// its derivative dF/dalpha = (dF/da) / (dalpha/da) from the same series (P is what the flat-punch
// theorem says it must be: a check, not used), its energy int F dalpha by Gauss-Legendre over a.
// The dent: inside the patch (r <= a) the face conforms to the sphere, u = alpha - r^2 / (2R),
// rate 1; outside, with s2 = sigma^2 = 1 - a/r,
//     u = (a^2 / R) [A(lambda) - 1/2 + s2 V(tau, sigma)],
// V a Chebyshev table of the sphere's outer profile (sphere_on_layer.hpp), smooth in sigma (the
// profile's square-root terms cancel at the edge to O(s2^1.5)) and exactly -1 at sigma = 0, which
// is the face's slope -a/R at r = a+: u is C^1 where a node enters the patch. The rate
// du/dalpha is the derivative of the same table, (du/da) / (dalpha/da) at fixed r: the Jacobian
// then holds the exact derivative of the residual, and the rate is exactly 1 at r = a. (It is the
// unit flat punch's profile to the tables' accuracy, ~1e-3: Shield's theorem.) Odd in alpha
// (force, dent) and even (stiffness, energy, rate) as the power laws (local_contact_law.hpp).
// Units mm, N, MPa.
#pragma once

#include "contact/hertz_dent.hpp"
#include "contact/support_kernel.hpp"
#include "core/chebyshev.hpp"

namespace si {

class LayerContactLaw {
 public:
  // max_radius_over_h: the largest a / h tabulated (the law throws beyond it).
  LayerContactLaw(const SupportSpec& spec, double sphere_radius, double max_radius_over_h = 4);

  double modulus() const { return modulus_; }  // M, MPa
  double thickness() const { return h_; }      // h, mm
  double radius() const { return R_; }         // R, mm

  double contact_radius(double alpha) const;  // a(|alpha|), mm
  double force(double alpha) const;           // N
  double stiffness(double alpha) const;       // dF/dalpha, N/mm
  double energy(double alpha) const;          // int_0^alpha F, N mm
  double approach(double force) const;        // alpha(F), mm
  DentValue dent(double r, double alpha) const;

  // The dent at one approach for many r (every node's gap at one Newton iterate): the contact
  // radius and the tables' slice at it computed once.
  class Dent {
   public:
    DentValue at(double r) const;

   private:
    friend class LayerContactLaw;
    double depth_ = 0, sign_ = 1, a_ = 0, R_ = 1;
    double A_ = 1, A_a_ = 0;   // A(lambda) and dA/da at a
    ChebyshevSeries V_, V_a_;  // V(tau(a), .) and dV/da(tau(a), .), series in sigma
  };
  Dent dent_at(double alpha) const;

  // The tables at lambda = a / h in [0, max_radius_over_h]: A, B, P of the header.
  double approach_ratio(double lambda) const;
  double force_ratio(double lambda) const;
  double punch_ratio(double lambda) const;

 private:
  double lambda_of_alpha(double alpha) const;  // alpha >= 0
  double tau(double lambda) const;             // the tables' variable (lambda / lambda_max)^0.5
  double slope(const ChebyshevSeries& f, double lambda) const;  // d f / d lambda
  double R_, h_, modulus_, lambda_max_;
  ChebyshevSeries approach_, force_, punch_;
  ChebyshevTable2 outer_;  // V in (tau, sigma)
};

}  // namespace si
