#include "indentation/active_set_solver.hpp"

#include <cmath>

#include "core/error.hpp"

namespace si {

ActiveSetResult solve_active_set(IndentationProblem& problem, cont::Vector& z, double h,
                                 double tolerance, int max_iterations) {
  ActiveSetResult out;
  cont::Vector F;
  for (int k = 0;; ++k) {
    if (!problem.residual(z, h, F)) {
      out.reason = "the residual cannot be evaluated (an element inverted?)";
      return out;
    }
    const double norm = F.lpNorm<Eigen::Infinity>();
    out.residual_norms.push_back(norm);
    // The residual of the min function is zero exactly at a KKT point, so a small residual is
    // the test. Requiring the active set to repeat as well never ends when a node sits at the
    // tie lambda = kappa g: it flips at round-off (measured: residual 2e-9, set alternating).
    if (norm <= tolerance) {
      out.converged = true;
      out.iterations = k;
      return out;
    }
    if (!std::isfinite(norm) || k == max_iterations) {
      out.iterations = k;
      out.reason = "no convergence in " + std::to_string(k) + " active-set iterations";
      return out;
    }
    if (!problem.factorize(z, h)) {
      out.reason = "the Newton matrix is singular";
      return out;
    }
    cont::Vector dz = -F;
    if (!problem.solve(dz)) {
      out.reason = "the linear solve failed";
      return out;
    }
    z += dz;
  }
}

}  // namespace si
