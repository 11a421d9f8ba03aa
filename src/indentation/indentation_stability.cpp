// The stability of a converged indentation point (docs/theory/continuation.md 9, 12): the
// Hessian of the Lagrangian L = Pi(x) - sum lambda_i g_i(x) in the shell's chart coordinates,
// restricted to the directions that keep the strongly active contact constraints.
//
// The shell rows of F are r(x) - sum lambda_i G_i (rotation rows on the current axes), and the
// Jacobian's shell block is their derivative K - sum lambda_i dG_i with respect to increments q
// about the current axes. A chart increment dx moves them by q = T dx (shell_chart.hpp), so the
// chart gradient of L is T' (r - sum lambda_i G_i) and its derivative
//     H = T' ((K - sum lambda_i dG_i) T + D) + (dT'/dx) (r - sum lambda_i G_i),
// whose last term and D vanish with the residual at a converged point: H = T' J_xx, J_xx the
// Jacobian's shell block after the chart transform. It is symmetric to the Newton tolerance; its
// symmetric part is analysed. The constraint rows are G_i' T (for linear kinematics T = I, and
// the gaps are linear: H = K). A mode v in chart coordinates is the shell part of z; the active
// multipliers' part solves H v = A' mu in the least-squares sense (a null vector of the Jacobian
// at a critical point), inactive multipliers stay 0.
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "continuation/cholmod_factorization.hpp"
#include "continuation/penalized_stability.hpp"
#include "continuation/stability_analysis.hpp"
#include "core/error.hpp"
#include "indentation/indentation_problem.hpp"

namespace si {
namespace {

// Keeps the terms' caches (the gaps' Newton guesses) as they were before the analysis, which
// evaluates the gaps again: the guesses steer the next solve's gap iterations at the level of
// round-off, and the path must be the same with path.stability as without it.
class CachesKept {
 public:
  explicit CachesKept(const std::vector<std::unique_ptr<ContactTerm>>& terms) : terms_(terms) {
    for (const auto& t : terms_) kept_.push_back(t->caches());
  }
  ~CachesKept() {
    for (std::size_t k = 0; k < terms_.size(); ++k) terms_[k]->restore_caches(std::move(kept_[k]));
  }
  CachesKept(const CachesKept&) = delete;
  CachesKept& operator=(const CachesKept&) = delete;

 private:
  const std::vector<std::unique_ptr<ContactTerm>>& terms_;
  std::vector<std::vector<double>> kept_;
};

}  // namespace

bool IndentationProblem::provides_stability() const {
  return options_.local.kind == LocalLawKind::kNone;
}

IndentationProblem::StabilityMatrices IndentationProblem::stability_matrices(const cont::Vector& z,
                                                                             double h) {
  SI_REQUIRE(provides_stability(),
             "indentation: stability is not provided with a local contact law");
  const CachesKept kept(parts_.terms);
  const int nf = shell_.size();
  SparseMatrix J;  // assembled here unless factorize() was at this very point
  SparseMatrix T;
  if (factored_at(z, h)) {
    T = ShellChart::transform(nf, factored_->rotations);
  } else {
    cont::Vector r_free;
    const std::vector<NodeState>& states = shell_terms(z, h, r_free);
    // The Jacobian as factorize() assembles it, in a copy: the solver may still read jacobian_.
    J = jacobian_;
    const SparseMatrix& K = shell_.tangent(z.head(nf));
    std::fill(J.valuePtr(), J.valuePtr() + J.nonZeros(), 0.0);
    for (int k = 0; k < K.nonZeros(); ++k) J.valuePtr()[k_to_j_[k]] = K.valuePtr()[k];
    const TermPoint p{z, h, states};
    for (const auto& t : parts_.terms) t->add_jacobian(p, J.valuePtr(), nullptr);
    T = ShellChart::transform(nf, shell_.to_chart(z.head(nf), r_free, J));
  }

  StabilityMatrices m;
  const SparseMatrix Jxx = (J.size() > 0 ? J : jacobian_).topLeftCorner(nf, nf);
  const SparseMatrix H = SparseMatrix(T.transpose()) * Jxx;
  const SparseMatrix Ht = H.transpose();
  m.H = 0.5 * (H + Ht);
  m.asymmetry = SparseMatrix(H - Ht).norm() / H.norm();
  m.A = active_constraint_gradients(z, h, &m.multipliers) * T;
  return m;
}

bool IndentationProblem::factored_at(const cont::Vector& z, double h) const {
  return factored_ && factored_->h == h && factored_->z.size() == z.size() && factored_->z == z;
}

bool IndentationProblem::stability(const cont::Vector& z, double h, int modes,
                                   cont::Stability& out) {
  if (penalized_stability(z, h, modes, out)) {
    ++counters_.stability_from_preconditioner;
    return true;
  }
  ++counters_.stability_direct;
  StabilityMatrices m;
  try {
    m = stability_matrices(z, h);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    return false;
  }
  cont::StabilityOptions options;
  options.factorization = cont::cholmod_first_factorization();
  if (!cont::analyse_stability(m.H, m.A, modes, out, options)) return false;
  complete_modes([&m](const cont::Vector& v) { return cont::Vector(m.H * v); }, m.A, m.multipliers,
                 out.modes);
  return true;
}

// At a point the continuation has just factored (it does before it asks), the Krylov solver's
// preconditioner made anew with the strongly active rows as penalties is P = H + rho A'A, whose
// Cholesky decides stability exactly when it succeeds and whose solves give the lowest
// eigenpairs (continuation/penalized_stability.hpp); it then serves the path as its
// preconditioner. (It did not spare the path any of its own refreshes, measured: those come
// within 2-3 linearisations of every step whatever factor it starts from; what this route
// saves is Z, Z'HZ and its factorization, docs/performance.md.) Where P is not positive
// definite (at or past a critical point) the direct analysis below takes over.
bool IndentationProblem::penalized_stability(const cont::Vector& z, double h, int modes,
                                             cont::Stability& out) {
  if (!factored_at(z, h)) return false;
  std::vector<int> multipliers;
  {
    const CachesKept kept(parts_.terms);
    active_constraint_gradients(z, h, &multipliers);
  }
  const int nf = shell_.size();
  std::vector<int> rows;
  for (int index : multipliers) rows.push_back(index - nf);
  const std::optional<PenalizedShell> shell = solver_->penalized_shell(rows);
  if (!shell) return false;
  cont::EigenOptions eigen;
  if (!cont::stability_from_penalized(shell->solve, shell->gradients, nf, modes, eigen, out))
    return false;
  // H v = sym(T' J_xx) v without forming H: (T' J_xx v + J_xx' T v) / 2.
  const SparseMatrix T = ShellChart::transform(nf, factored_->rotations);
  const auto shell_block = [this, nf](const cont::Vector& v, bool transposed) {
    cont::Vector full = cont::Vector::Zero(size());
    full.head(nf) = v;
    return cont::Vector(
        (transposed ? cont::Vector(jacobian_.transpose() * full) : cont::Vector(jacobian_ * full))
            .head(nf));
  };
  const auto H_times = [&](const cont::Vector& v) {
    return cont::Vector(0.5 * (T.transpose() * shell_block(v, false) + shell_block(T * v, true)));
  };
  complete_modes(H_times, shell->gradients, multipliers, out.modes);
  return true;
}

void IndentationProblem::complete_modes(
    const std::function<cont::Vector(const cont::Vector&)>& H_times, const SparseMatrix& A,
    const std::vector<int>& multipliers, std::vector<cont::Vector>& modes) const {
  const int nf = shell_.size();
  for (cont::Vector& v : modes) {
    cont::Vector mode = cont::Vector::Zero(size());
    mode.head(nf) = v;
    // One sign whichever route computed it: the largest shell component positive.
    Eigen::Index largest = 0;
    v.cwiseAbs().maxCoeff(&largest);
    if (v[largest] < 0) mode.head(nf) = -v;
    if (!multipliers.empty()) {
      // The Jacobian's multiplier columns are -G_i (not +A' of the bordered matrix).
      const cont::Vector mu = -cont::multiplier_direction_from_product(A, H_times(mode.head(nf)));
      for (std::size_t k = 0; k < multipliers.size(); ++k)
        mode[multipliers[k]] = mu[static_cast<Eigen::Index>(k)];
    }
    v = std::move(mode);
  }
}

}  // namespace si
