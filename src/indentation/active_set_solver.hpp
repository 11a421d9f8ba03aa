// The independent cross-check of the KINSOL contact solve: the primal-dual active-set method
// (Hintermueller, Ito & Kunisch, SIAM J. Optim. 13, 2002), i.e. undamped semismooth Newton on
// the complementarity system written with the min function (contact/ncp_function.hpp). A node
// is active (its gap row is enforced) where lambda_i > kappa g_i; each iteration solves the
// Newton system for that active set. Own code throughout: no KINSOL, no line search. It
// stops when the residual is below the tolerance.
//
// It needs an IndentationProblem built with NcpFunction::kMin.
#pragma once

#include <string>
#include <vector>

#include "indentation/indentation_problem.hpp"

namespace si {

struct ActiveSetResult {
  bool converged = false;
  int iterations = 0;
  std::vector<double> residual_norms;  // ||F||_inf before each iteration and at the end
  std::string reason;                  // why it failed; empty on success
};

// Solves at depth h from z (overwritten). Converged: ||F||_inf <= tolerance (units of F: N).
ActiveSetResult solve_active_set(IndentationProblem& problem, cont::Vector& z, double h,
                                 double tolerance, int max_iterations = 50);

}  // namespace si
