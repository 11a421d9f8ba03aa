// The one SUNDIALS adapter of the library: a KINSOL Newton iteration (optionally with line
// search) whose linear solver is a custom DIRECT SUNLinearSolver calling the system's own
// setup/solve pair over a custom, empty SUNMatrix (docs/toolchain.md §3(c)). Full Newton
// (KINSetMaxSetupCalls(1)); KINSOL's error messages go into NewtonResult::reason, not stderr.
#pragma once

#include <string>
#include <vector>

#include "continuation/problem.hpp"
#include "continuation/settings.hpp"

namespace si::cont {

// A square nonlinear system R(u) = 0 as the corrector sees it. Each call returns false on a
// recoverable failure (cannot evaluate, singular matrix...).
class NonlinearSystem {
 public:
  virtual ~NonlinearSystem() = default;
  virtual bool residual(const Vector& u, Vector& r) = 0;
  // Linearise dR/du at u and factor it.
  virtual bool setup(const Vector& u) = 0;
  // (dR/du) y = b in place, with the last setup().
  virtual bool solve(Vector& b) = 0;
  // Why the last call that returned false failed (Problem::failure); empty if not known.
  virtual std::string failure() const { return {}; }
  // What unknown i is (Problem::unknown_name); empty if not known.
  virtual std::string unknown_name(int) const { return {}; }
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  // ||R||_inf at the start and after each Newton iteration (the last entry is the final one).
  std::vector<double> residual_norms;
  double tolerance = 0.0;  // the absolute ||R||_inf tolerance that was used
  int flag = 0;            // KINSol's return flag (0 when KINSOL was not needed)
  std::string flag_name;   // e.g. "KIN_SUCCESS", "KIN_LINESEARCH_NONCONV"
  std::string reason;      // why it failed (KINSOL's messages included); empty on success
};

// Newton on `system` from u (overwritten by the last iterate). Converged means
// ||R(u)||_inf <= relative_tolerance * max(||R(u_start)||_inf, residual_scale), checked here on
// the returned u whatever KINSOL's flag. Throws std::runtime_error only when SUNDIALS itself
// cannot be set up (a failed KINSOL call other than KINSol, naming the call).
NewtonResult newton_solve(NonlinearSystem& system, Vector& u, const NewtonSettings& settings);

// The corrector at a fixed parameter: F(x, p) = 0 for x, from x (overwritten).
NewtonResult solve_at(Problem& problem, Vector& x, double p, const NewtonSettings& settings);

}  // namespace si::cont
