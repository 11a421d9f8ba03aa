#include "analysis/active_set_solver.hpp"

#include <cmath>

#include "core/error.hpp"

namespace si {

ActiveSetResult solve_active_set(IndentationProblem& problem, cont::Vector& z, double h,
                                 double tolerance, int max_iterations) {
  ActiveSetResult out;
  cont::Vector F;
  std::vector<int> previous_set;
  for (int k = 0;; ++k) {
    if (!problem.residual(z, h, F)) {
      out.reason = "the residual cannot be evaluated (an element inverted?)";
      return out;
    }
    const double norm = F.lpNorm<Eigen::Infinity>();
    out.residual_norms.push_back(norm);
    const std::vector<int> set = problem.signature(z, h);
    if (norm <= tolerance && (k > 0 && set == previous_set)) {
      out.converged = true;
      out.iterations = k;
      return out;
    }
    if (!std::isfinite(norm) || k == max_iterations) {
      out.iterations = k;
      out.reason = "no convergence in " + std::to_string(k) + " active-set iterations";
      return out;
    }
    previous_set = set;
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
