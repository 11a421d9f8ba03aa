// Rigid super-quadric (Barr 1981) centred at the pose position with semi-axes a, b, c along
// the global x1, x2, x3 and exponents e1 (x3 profile), e2 (x1-x2 cross-section):
//   F(x) = (|X/a|^(2/e2) + |Y/b|^(2/e2))^(e2/e1) + |Z/c|^(2/e1),  X = x - centre.
// a = b = c = R, e1 = e2 = 1 is the paper's sphere, eq 29 (f = F - 1).
//
// Signed distance: a super-quadric has no closed-form distance. We use the first-order distance
// g/|grad g| of the radial function g = F^(e1/2) - 1, which is homogeneous of degree one in X.
// It vanishes on the surface with the exact gradient there (the normal of the paper's eq 32,
// grad f/|grad f|), so it is the true distance to first order, and it is exact for a sphere
// (g = |X|/R - 1, g/|grad g| = |X| - R). The normal returned is grad g/|grad g| (eq 32) and the
// "hessian" its derivative (I - n n^T) grad^2 g/|grad g|; both are exact for the sphere.
#pragma once

#include "contact/indenter.hpp"

namespace si {

struct SuperquadricShape {
  double a = 1, b = 1, c = 1;  // semi-axes along x1, x2, x3
  double e1 = 1, e2 = 1;       // exponents, 0 < e <= 2 (convex)
};

class SuperquadricIndenter : public Indenter {
 public:
  SuperquadricIndenter(const SuperquadricShape& shape, const IndenterPose& pose);
  std::string name() const override { return "superquadric"; }
  // Paper eq 29 generalised: F(x) - 1.
  double implicit(const Vector3d& x, double travel) const override;
  double signed_distance(const Vector3d& x, double travel, Vector3d* normal,
                         Matrix3d* hessian) const override;

 private:
  // g = F^(e1/2) - 1 at x with its gradient and Hessian in x.
  double radial(const Vector3d& x, double travel, Vector3d* grad, Matrix3d* hess) const;
  SuperquadricShape shape_;
};

}  // namespace si
