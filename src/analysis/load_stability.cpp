// The stability of a converged point of the load problem (docs/theory/continuation.md 9, 12):
// the Hessian of the potential Pi(x) = U(x) - lambda W(x) in the shell's chart coordinates.
//
// The residual's rows are F = r(x) - lambda f_ext with rotation rows on the current axes, and the
// Jacobian J = dF/dx = (K - lambda K_p) T + D (load_problem.hpp) is their derivative along chart
// increments. The chart gradient of Pi is T' F, so its derivative is T' J + (dT'/dx) F, and at a
// converged point (F = 0) the Hessian is H = T' J. It is symmetric when the loads are
// conservative: dead loads, and a follower pressure on a surface whose boundary does not move
// (its work is p times the enclosed volume, whose gradient is the consistent nodal force of the
// pressure: Schweizerhof & Ramm 1984, Bufler 1984). A follower pressure with a free edge is not
// conservative, and its skew part is not small: the symmetric part is analysed in every case and
// the skew part's size is reported (stability_matrix().asymmetry), so that a run can tell.
// Linear kinematics: H = K, the reference stiffness.
#include <utility>

#include "analysis/load_problem.hpp"
#include "continuation/cholmod_factorization.hpp"
#include "continuation/stability_analysis.hpp"
#include "core/error.hpp"

namespace si {

LoadProblem::StabilityMatrix LoadProblem::stability_matrix(const cont::Vector& x, double lambda) {
  StabilityMatrix m;
  if (!nonlinear()) {
    if (!factorized_) factorize(x, lambda);
    m.H = jacobian_;
    return m;
  }
  SparseMatrix J;  // assembled here unless factorize() was at this very point
  std::vector<ShellChart::RotationBlock> rotations;
  const bool factored_here =
      factored_x_.size() == x.size() && factored_lambda_ == lambda && factored_x_ == x;
  if (!factored_here) J = chart_jacobian(x, lambda, rotations);
  const SparseMatrix T = ShellChart::transform(size(), factored_here ? rotations_ : rotations);
  const SparseMatrix H = SparseMatrix(T.transpose()) * (factored_here ? jacobian_ : J);
  const SparseMatrix Ht = H.transpose();
  m.H = 0.5 * (H + Ht);
  m.asymmetry = SparseMatrix(H - Ht).norm() / H.norm();
  return m;
}

bool LoadProblem::stability(const cont::Vector& x, double lambda, int modes, cont::Stability& out) {
  StabilityMatrix m;
  try {
    m = stability_matrix(x, lambda);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    last_error_ = e.reason();
    return false;
  }
  cont::StabilityOptions options;
  options.factorization = cont::cholmod_first_factorization();
  const SparseMatrix no_constraints(0, size());
  return cont::analyse_stability(m.H, no_constraints, modes, out, options);
}

}  // namespace si
