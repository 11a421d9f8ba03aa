// Keller's bordering (Keller 1977, "Numerical solution of bifurcation and nonlinear eigenvalue
// problems", §3; also Allgower & Georg 2003, §4.1): solves the (n+1) x (n+1) system
//     [ J    F_p ] [y]   [b   ]
//     [ c_x' c_p ] [q] = [beta]
// with the problem's own factorization of J = dF/dx and two right-hand sides, J y1 = b and
// J y2 = F_p:  q = (beta - <c_x, y1>) / (w^2 c_p - <c_x, y2>),  y = y1 - q y2.
// The border row acts as (v, r) -> <c_x, v> + w^2 c_p r with the problem's inner product and
// the parameter weight w, so c = (c_x, c_p) is a tangent-like vector in the arclength metric.
// J may be singular at a simple limit point while the bordered matrix is not; the elimination
// then loses accuracy only in a neighbourhood of relative size ~ eps * cond (Keller 1977).
#pragma once

#include "continuation/problem.hpp"

namespace si::cont {

class BorderedSolver {
 public:
  BorderedSolver(Problem& problem, double weight) : problem_(problem), weight_(weight) {}

  // Factor J at (x, p) and solve J y2 = F_p. false on a recoverable failure.
  bool setup(const Vector& x, double p);

  // The system above with the last setup(); b is overwritten by y. false on failure.
  bool solve(const Vector& c_x, double c_p, Vector& b, double beta, double& q);

  // The unit tangent (t_x, t_p) of the branch at the last setup(): [J F_p] t = 0, normalised in
  // the arclength norm and oriented by the reference direction (ref_x may be empty = 0):
  // the border row is the reference, so <ref, t> > 0 (Keller 1977, orientation by continuity).
  bool tangent(const Vector& ref_x, double ref_p, Vector& t_x, double& t_p);

  // <a, b> + w^2 a_p b_p, the arclength inner product.
  double inner(const Vector& a_x, double a_p, const Vector& b_x, double b_p) const {
    return problem_.inner(a_x, b_x) + weight_ * weight_ * a_p * b_p;
  }
  double weight() const { return weight_; }
  const Vector& y2() const { return y2_; }  // J^-1 F_p

 private:
  double border_denominator(const Vector& c_x, double c_p) const;

  Problem& problem_;
  double weight_;
  Vector y2_;
};

}  // namespace si::cont
