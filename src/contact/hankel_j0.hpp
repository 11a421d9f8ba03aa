// The zeroth-order Hankel-type transform
//     F(rho) = int_0^inf f(x) J0(x rho) dx,    0 < rho <= rho_max,
// of a smooth f on [0, inf) with an algebraic tail f(x) = t1 / x + t3 / x^3 + O(x^-5): the radial
// displacement field of a point force on a surface whose compliance per wave is f (the face
// kernel of contact/face_influence.hpp). The tail makes the integral converge only
// conditionally and F diverge like -t1 ln rho at rho -> 0, so it is taken in closed form,
//     t1 (1 + x^2)^-1/2          ->  t1 I0(rho/2) K0(rho/2)                     (G&R 6.552.1)
//     s3 (1 + x^2)^-3/2          ->  s3 (rho/2) [I0 K1 - I1 K0](rho/2),   s3 = t3 + t1 / 2
// (the second is -(1/a) d/da of the first at a = 1, for (x^2 + a^2)^-1/2), and the rest, which
// decays like x^-5, through Bessel's integral J0(x rho) = (2/pi) int_0^{pi/2} cos(x rho sin t) dt:
// its cosine transform by Gauss-Legendre panels on [0, x_max] as a Chebyshev series, then the
// integral over t by Gauss, into a Chebyshev series in rho (smooth at rho = 0: its integrand is
// absolutely integrable with three moments). F + t1 ln rho, smooth
// but for rho^2 ln rho terms, is then sampled for cubic Hermite interpolation (the contact columns
// evaluate F ~1e6 times; Clenshaw's recurrence and the Bessel functions would dominate); within
// the first samples, where those terms are not cubics, F is evaluated in closed form.
#pragma once

#include <functional>
#include <vector>

#include "core/chebyshev.hpp"
#include "section/gauss_legendre.hpp"

namespace si {

class HankelJ0 {
 public:
  // f: the function (evaluated ~1e4 times), t1 and t3 its tail's coefficients. x_max: where the
  // remainder's integral stops (its tail beyond is ~x_max^-4 of f's scale).
  HankelJ0(const std::function<double(double)>& f, double t1, double t3, double rho_max,
           double x_max = 60);

  double rho_max() const { return rho_max_; }
  // F(rho), 0 < rho <= rho_max.
  double operator()(double rho) const;
  // int_0^b rho F(rho) d rho, 0 <= b <= rho_max: a disc's share (finite, F being ~ln rho at 0).
  double moment(double b) const;

 private:
  double direct(double rho) const;  // closed forms plus the remainder's series
  double t1_ = 0, s3_ = 0, rho_max_ = 0;
  ChebyshevSeries remainder_;
  GaussRule moment_rule_;  // moment()'s, made once (each node's own disc asks for one)
  double step_ = 0;
  // F + t1 ln rho and its slope at rho_j = j step_, j >= 1 (index 0 unused).
  std::vector<double> value_, slope_;
};

}  // namespace si
