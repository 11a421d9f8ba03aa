// Solves with a matrix bordered by one row and one column,
//     [ A    c ] [ y  ]   [ r  ]
//     [ d^T  e ] [ y_a] = [ r_a ],
// by block elimination through a solver for A alone (Golub & Van Loan, Matrix Computations,
// 4th ed., 2013, section 4.6 on bordered systems):
//     s = e - d^T A^-1 c,   y_a = (r_a - d^T A^-1 r) / s,   y = A^-1 r - (A^-1 c) y_a.
// A^-1 c is computed once per factorization, so each solve costs one solve with A. Why: the
// power-law local contact adds the single unknown alpha whose column couples every
// complementarity row (indentation_problem.hpp); without the border the Jacobian keeps the shape
// the preconditioned Krylov solver condenses (contact_jacobian_solver.hpp), which is several
// times cheaper than an LU of the bordered matrix (docs/theory/local-indentation.md section 6).
// Stable when |s| is not small against |e| + |d^T A^-1 c|; factorize() reports a vanishing s.
#pragma once

#include <cmath>

#include <Eigen/Dense>

namespace si {

class BorderedSolve {
 public:
  // inner(x) returns A^-1 x. False if A^-1 c is not finite or s vanishes to roundoff (the
  // caller then solves the bordered matrix another way).
  template <class InnerSolve>
  bool factorize(const Eigen::VectorXd& c, const Eigen::VectorXd& d, double e, InnerSolve&& inner) {
    d_ = d;
    inverse_c_ = inner(c);
    if (!inverse_c_.allFinite()) return false;
    const double coupling = d_.dot(inverse_c_);
    schur_ = e - coupling;
    return std::abs(schur_) > 1e-12 * (std::abs(e) + std::abs(coupling)) && std::isfinite(schur_);
  }

  // rhs = [r ; r_a], overwritten by [y ; y_a].
  template <class InnerSolve>
  void solve(Eigen::VectorXd& rhs, InnerSolve&& inner) const {
    const Eigen::Index n = inverse_c_.size();
    Eigen::VectorXd y = inner(rhs.head(n));
    const double ya = (rhs[n] - d_.dot(y)) / schur_;
    rhs.head(n) = y - inverse_c_ * ya;
    rhs[n] = ya;
  }

 private:
  Eigen::VectorXd d_;
  Eigen::VectorXd inverse_c_;
  double schur_ = 0;
};

}  // namespace si
