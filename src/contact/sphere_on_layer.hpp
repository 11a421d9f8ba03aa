// Frictionless contact of a rigid sphere with a support of finite thickness h whose surface
// compliance is the half-space's times 1 + kappa(k h) (support_kernel.hpp): the axisymmetric
// (angle-averaged) problem reduced to a Fredholm equation of the second kind (Sneddon's method;
// Dhaliwal 1970, Int. J. Eng. Sci. 8:273, for the bonded layer; derivation in
// docs/theory/local-indentation.md 6.5). Units here: h = 1, the modulus M = 2 / H_inf = 1, the
// sphere's radius R = 1; the law (layer_contact_law.hpp) restores them.
//
// The pressure on the contact radius a = lambda (in h) is written through g on [0, a],
//     p(r) = g(a) / (a^2 - r^2)^0.5 - int_r^a g'(t) / (t^2 - r^2)^0.5 dt,
// whose Hankel transform is int_0^a g(t) cos(k t) dt. The surface displacement inside the
// contact, its Abel transform, gives
//     g(t) + int_0^a K(t, s) g(s) ds = (1/pi) (alpha - t^2),
//     K(t, s) = (1/pi) [Kc(t - s) + Kc(t + s)],   Kc(y) = int_0^inf kappa(x) cos(x y) dx,
// for a sphere at approach alpha; g = alpha g1 - g2 with g1, g2 the solutions for the right-hand
// sides 1/pi and t^2/pi. A smooth contact edge (no square-root pressure) needs g(a) = 0, so
//     alpha = g2(a) / g1(a),   F = 2 pi int_0^a g dt,
// and g1 is the flat punch of unit depth, whose force 2 pi int g1 is dF/dalpha (the incremental
// stiffness of a smooth indenter is the flat punch's at the current radius). Outside (r > a) the
// face displaces by the Hankel integral of the pressure; with J0(x r) = (2/pi) int_0^r
// cos(x u) / (r^2 - u^2)^0.5 du and u = r sin theta it becomes
//     u(r) = 2 int_0^beta f(r sin theta) dtheta + 2 int_beta^pi/2 (K g)(r sin theta) dtheta,
// beta = asin(a / r), f the right-hand side, (K g)(u) = int_0^a K(u, s) g(s) ds: no Bessel
// function, and the first term in closed form. For kappa = 0 all of this is Hertz's:
// g = (alpha - t^2)/pi, alpha = a^2, F = (4/3) a^3, the punch's 2 a, and u the half-space's
// profile (hertz_dent.hpp). The face is taken at rest beyond r = kDentRange h (= 16 h), where
// every finite support's displacement is below the tables' accuracy.
// Gauss-Legendre (Nystrom) on [0, a], g between the nodes by Nystrom's interpolation.
#pragma once

#include <vector>

#include "contact/support_kernel.hpp"

namespace si {

struct SphereOnLayerSolution {
  double radius = 0;    // a (in h)
  double approach = 0;  // alpha / a^2   (alpha R / a^2 with units)
  double force = 0;     // F / a^3       (F R / (M a^3))
  double punch = 0;     // (dF/dalpha) / a   ((dF/dalpha) / (M a)): the flat punch of radius a
  Eigen::VectorXd t, w, g1, g2;  // the Nystrom nodes, weights and the two solutions
};

class SphereOnLayer {
 public:
  // nodes: Gauss points on [0, a]. The kernel's cosine transform must reach a + kDentRange
  // (outer_face) and 2 a (solve).
  explicit SphereOnLayer(const SupportKernel& kernel, int nodes = 32);
  static constexpr double kDentRange = 16;

  // a >= 0 (a = 0: Hertz's limits).
  SphereOnLayerSolution solve(double a) const;
  // The face's displacement at r = a / s (0 < s < 1) outside the contact, over a^2 (the sphere's
  // u / (a^2 / R)), and the flat punch's of unit depth (du/dalpha of the sphere): per s.
  struct OuterFace {
    std::vector<double> sphere, punch;
  };
  OuterFace outer_face(const SphereOnLayerSolution& s, const std::vector<double>& a_over_r) const;
  // (K g1)(u) and (K g2)(u) = int_0^a K(u, s) g(s) ds by the Nystrom rule, any u >= 0 (for u
  // in [0, a], g(u) = f(u) - (K g)(u) interpolates the solution between the nodes).
  Vector2d applied_kernel(const SphereOnLayerSolution& s, double u) const;

 private:
  double kernel(double t, double s) const;
  const SupportKernel& kernel_;
  int nodes_;
};

}  // namespace si
