#include "indentation/contact_jacobian_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/error.hpp"

namespace si {
namespace {

// Condensation floor (see the header): a fully active candidate becomes a penalty kappa / eps.
// 1e-8 keeps H's condition within what a double-precision Cholesky resolves to about 1e-8, and
// the preconditioned operator within about 1e-6 of the identity on the contact rows.
constexpr double kCondensationFloor = 1e-8;
// A fresh factor needs 1-2 GMRES products per solve on the paper's cap; refreshing it once a solve
// needs more than 3 was the fastest of 3, 6 and 10 on the cap at 1e4 unknowns
// (docs/performance.md); the factor is kept across factorize() calls (Newton iterations, steps)
// until a solve needs more than this, or it is older than kMaxPreconditionerAge linearisations.
constexpr int kRefreshProducts = 3;
constexpr int kMaxPreconditionerAge = 20;
}  // namespace

ContactJacobianSolver::ContactJacobianSolver(double kappa, LinearSolverKind fallback,
                                             double relative_tolerance)
    : ContactJacobianSolver(
          kappa, [fallback] { return make_linear_solver(fallback); }, relative_tolerance) {}

ContactJacobianSolver::ContactJacobianSolver(double kappa, LinearSolverFactory fallback,
                                             double relative_tolerance)
    : kappa_(kappa), lu_(std::move(fallback)) {
  SI_REQUIRE(relative_tolerance > 0 && relative_tolerance < 1,
             "contact Jacobian: the Krylov tolerance must lie in (0, 1)");
  gmres_.relative_tolerance = relative_tolerance;
}

ContactJacobianSolver::~ContactJacobianSolver() = default;

int ContactJacobianSolver::shell_slot(int row, int col) const {
  const int* begin = H_.innerIndexPtr() + H_.outerIndexPtr()[col];
  const int* end = H_.innerIndexPtr() + H_.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  SI_REQUIRE(it != end && *it == row, "contact Jacobian: entry outside the shell pattern");
  return static_cast<int>(it - H_.innerIndexPtr());
}

// The shell block's pattern is that of the assembled shell: fixed for the problem.
void ContactJacobianSolver::analyze_shell(const SparseMatrix& J, int num_shell) {
  num_shell_ = num_shell;
  H_ = J.topLeftCorner(num_shell, num_shell);
  H_.makeCompressed();
  mirror_.resize(H_.nonZeros());
  for (int c = 0; c < num_shell; ++c)
    for (int k = H_.outerIndexPtr()[c]; k < H_.outerIndexPtr()[c + 1]; ++k)
      mirror_[k] = shell_slot(c, H_.innerIndexPtr()[k]);  // shell patterns are symmetric
  diagonal_slot_.resize(num_shell);
  for (int c = 0; c < num_shell; ++c) diagonal_slot_[c] = shell_slot(c, c);
  cholesky_ = make_linear_solver(LinearSolverKind::kCholmod);
  cholesky_->analyze(H_);
  rotation_slots_.clear();
  analyzed_outer_.clear();
  has_preconditioner_ = false;
}

// J's pattern changes with the candidate set: new slots, new rows. The Cholesky factor stays:
// it depends on the shell block and the rows it condensed, which the candidates appended by
// Problem::adapt leave as they were (factorize() lets GMRES carry the new rows).
void ContactJacobianSolver::map_jacobian(const SparseMatrix& J) {
  j_slot_.resize(H_.nonZeros());
  for (int c = 0; c < num_shell_; ++c) {
    const int* begin = J.innerIndexPtr() + J.outerIndexPtr()[c];
    const int* end = J.innerIndexPtr() + J.outerIndexPtr()[c + 1];
    for (int k = H_.outerIndexPtr()[c]; k < H_.outerIndexPtr()[c + 1]; ++k)
      j_slot_[k] =
          static_cast<int>(std::lower_bound(begin, end, H_.innerIndexPtr()[k]) - J.innerIndexPtr());
  }
  analyzed_outer_.assign(J.outerIndexPtr(), J.outerIndexPtr() + J.outerSize() + 1);
  row_slots_.clear();
  lu_.forget();
}

void ContactJacobianSolver::transpose_transform(
    const std::vector<ShellChart::RotationBlock>& rotations, Eigen::VectorXd& v) {
  for (const ShellChart::RotationBlock& r : rotations) {
    if (r.eq_a >= 0 && r.eq_b >= 0) {
      const double a = v[r.eq_a], b = v[r.eq_b];
      v[r.eq_a] = r.T(0, 0) * a + r.T(1, 0) * b;
      v[r.eq_b] = r.T(0, 1) * a + r.T(1, 1) * b;
    } else if (r.eq_a >= 0) {
      v[r.eq_a] *= r.T(0, 0);
    } else if (r.eq_b >= 0) {
      v[r.eq_b] *= r.T(1, 1);
    }
  }
}

// H = sym(T^T A) + condensed rows from the current linearisation; false if H is not positive
// definite.
bool ContactJacobianSolver::refresh_preconditioner() {
  return refresh_with(rows_, lu_out_of_memory_ ? Indefinite::kIfNeeded : Indefinite::kNone);
}

bool ContactJacobianSolver::factor_h() {
  try {
    ++counters_.cholesky;
    cholesky_->factorize(H_);
    return true;
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    refresh_failure_ = e.what();
    return false;
  }
}

bool ContactJacobianSolver::factor_shell_block(Indefinite indefinite) {
  if (indefinite != Indefinite::kOnly && factor_h()) {
    factor_ = cholesky_.get();
    return true;
  }
  if (indefinite == Indefinite::kNone) return false;
  // The LDL' of H itself: an exact preconditioner however many eigenvalues are negative. A
  // shifted Cholesky (H + sigma |diag|, Nocedal & Wright 2006, Alg. 3.3) was tried first: on the
  // 1e6 cap past 9.63 mm Newton then needed 21 iterations for a 0.24 mm step and failed its line
  // search (docs/performance.md), GMRES paying for every eigenvalue the shift moved.
  const std::string cholesky_failure = refresh_failure_;
  try {
    if (!ldlt_) ldlt_ = make_linear_solver(LinearSolverKind::kLdlt);
    ++counters_.ldlt;
    ldlt_->factorize(H_);  // analyses first; either may run out of memory: said with the Cholesky's
    factor_ = ldlt_.get();
    return true;
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    refresh_failure_ = cholesky_failure + "; its LDL' neither: " + e.what();
    return false;
  }
}

bool ContactJacobianSolver::refresh_with(const std::vector<ContactJacobianRow>& condensed,
                                         Indefinite indefinite) {
  if (rotation_slots_.empty())
    for (std::size_t i = 0; i < rotations_.size(); ++i) {
      const ShellChart::RotationBlock& r = rotations_[i];
      const int lead = r.eq_a >= 0 ? r.eq_a : r.eq_b;
      for (int k = H_.outerIndexPtr()[lead]; k < H_.outerIndexPtr()[lead + 1]; ++k) {
        const int c = H_.innerIndexPtr()[k];  // column c has row `lead` (symmetric pattern)
        rotation_slots_.push_back({r.eq_a >= 0 ? shell_slot(r.eq_a, c) : -1,
                                   r.eq_b >= 0 ? shell_slot(r.eq_b, c) : -1, static_cast<int>(i)});
      }
    }
  if (row_slots_.size() != rows_.size()) {
    row_slots_.assign(rows_.size(), {});
    for (std::size_t i = 0; i < rows_.size(); ++i)
      for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 5; ++c)
          row_slots_[i][5 * r + c] = rows_[i].eq[r] >= 0 && rows_[i].eq[c] >= 0
                                         ? shell_slot(rows_[i].eq[r], rows_[i].eq[c])
                                         : -1;
  }
  const double* jv = J_->valuePtr();
  Eigen::VectorXd m(H_.nonZeros());
  for (int k = 0; k < H_.nonZeros(); ++k) m[k] = jv[j_slot_[k]];
  for (const RotationSlots& s : rotation_slots_) {  // the rows of T^T A
    const Matrix2d& T = rotations_[s.block].T;
    if (s.a >= 0 && s.b >= 0) {
      const double a = m[s.a], b = m[s.b];
      m[s.a] = T(0, 0) * a + T(1, 0) * b;
      m[s.b] = T(0, 1) * a + T(1, 1) * b;
    } else if (s.a >= 0) {
      m[s.a] *= T(0, 0);
    } else {
      m[s.b] *= T(1, 1);
    }
  }
  double* hv = H_.valuePtr();
  for (int k = 0; k < H_.nonZeros(); ++k) hv[k] = 0.5 * (m[k] + m[mirror_[k]]);
  for (std::size_t i = 0; i < condensed.size(); ++i) {
    const ContactJacobianRow& row = condensed[i];
    if (row.b == 0.0) continue;
    const double w = row.b / row.a;
    for (int r = 0; r < 5; ++r)
      for (int c = 0; c < 5; ++c)
        if (row_slots_[i][5 * r + c] >= 0)
          hv[row_slots_[i][5 * r + c]] += w * row.gradient[r] * row.gradient[c];
  }
  has_preconditioner_ = false;
  if (!factor_shell_block(indefinite)) return false;
  coupled_.clear();
  if (!coupled_.build(coupling_, num_shell_, condensed, *factor_)) {
    refresh_failure_ = "the coupled rows' Woodbury correction is singular";
    return false;
  }
  refresh_failure_.clear();
  pre_rows_ = condensed;
  pre_rotations_ = rotations_;
  has_preconditioner_ = true;
  preconditioner_age_ = 0;
  last_products_ = 0;
  return true;
}

bool ContactJacobianSolver::refresh_penalized(const std::vector<int>& rows) {
  // Coupled rows (a compliant face) are no constraints to penalise.
  if (J_ == nullptr || use_lu_ || border_ || !coupling_.empty()) return false;
  // Weight 0 (b = 0: uncondensed) on every row but the listed ones, kappa / floor on those: the
  // floored a of a fully active row (factorize()), whatever its b.
  std::vector<ContactJacobianRow> condensed = rows_;
  for (ContactJacobianRow& row : condensed) row.b = 0.0;
  for (int i : rows) {
    SI_REQUIRE(i >= 0 && i < static_cast<int>(rows_.size()), "contact Jacobian: no such row");
    ContactJacobianRow& row = condensed[static_cast<std::size_t>(i)];
    row.b =
        rows_[static_cast<std::size_t>(i)].b > 0.0 ? rows_[static_cast<std::size_t>(i)].b : kappa_;
    row.a = kCondensationFloor * row.b / kappa_;
  }
  if (refresh_with(condensed, Indefinite::kNone))
    return true;  // the stability analysis needs H itself
  // What factorize() would have done at this linearisation.
  if (!refresh_preconditioner()) factor_fallback(true);
  return false;
}

Eigen::VectorXd ContactJacobianSolver::solve_shell_block(const Eigen::VectorXd& r) const {
  SI_REQUIRE(has_preconditioner_ && r.size() == num_shell_,
             "contact Jacobian: no shell factor to solve with");
  return factor_->solve(r);
}

SparseMatrix ContactJacobianSolver::chart_gradients(const std::vector<int>& rows) const {
  std::vector<Eigen::Triplet<double, int>> t;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const ContactJacobianRow& row = rows_[static_cast<std::size_t>(rows[k])];
    for (int c = 0; c < 5; ++c)
      if (row.eq[c] >= 0 && row.gradient[c] != 0.0)
        t.emplace_back(static_cast<int>(k), row.eq[c], row.gradient[c]);
  }
  SparseMatrix G(static_cast<Eigen::Index>(rows.size()), num_shell_);
  G.setFromTriplets(t.begin(), t.end());
  return G;
}

void ContactJacobianSolver::factor_fallback(bool may_ldlt) {
  // Both routes' reasons in one message: why the preconditioner could not be used, and why the
  // LU failed.
  const auto fail = [this](const std::string& lu_failure) {
    const std::string before =
        refresh_failure_.empty() ? "" : "the preconditioner's factor: " + refresh_failure_ + "; ";
    throw_numerical(before + "the LU of the contact Jacobian (" + std::to_string(J_->rows()) +
                    " unknowns): " + lu_failure);
  };
  if (lu_out_of_memory_) fail("out of memory before, not tried again");
  ++counters_.lu_fallbacks;
  try {
    lu_.factorize(*J_, num_shell_, coupling_);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::kNumerical) throw;
    // Out of memory (the LU of a 1e6-unknown shell needs more than its Cholesky factor): from
    // now on the LDL' of H preconditions GMRES where H has no Cholesky factor, and no LU is
    // tried. Near a singular J an LU's solves are the more accurate (measured on the roof's
    // fold: its force 1.45e-6 off the bifurcation's with a shifted H, 2.6e-7 with the LU), so
    // the LDL' is kept for where the LU is out of reach.
    if (lu_.out_of_memory()) {
      lu_out_of_memory_ = true;
      // H (from rows_) failed its Cholesky just before this fallback was called: the LDL' only.
      if (may_ldlt && refresh_with(rows_, Indefinite::kOnly) && (!border_ || prepare_border()))
        return;
    }
    fail(e.what());
  }
  use_lu_ = true;
}

void ContactJacobianSolver::factorize(const SparseMatrix& J, int num_shell,
                                      const std::vector<ShellChart::RotationBlock>& rotations,
                                      const std::vector<ContactJacobianRow>& rows, int border,
                                      RowCoupling coupling) {
  SI_REQUIRE(border == 0 || border == 1, "contact Jacobian: the border is 0 or 1 unknown");
  SI_REQUIRE(J.isCompressed() && J.rows() == J.cols() &&
                 J.rows() == num_shell + static_cast<int>(rows.size()) + border,
             "contact Jacobian: size does not match the shell and contact rows");
  border_ = border;
  if (num_shell != num_shell_) analyze_shell(J, num_shell);
  const bool same_pattern =
      static_cast<int>(analyzed_outer_.size()) == J.outerSize() + 1 &&
      std::equal(analyzed_outer_.begin(), analyzed_outer_.end(), J.outerIndexPtr());
  if (!same_pattern) map_jacobian(J);
  J_ = &J;
  coupling_ = std::move(coupling);
  rotations_ = rotations;
  // Rotation components of each gradient onto the chart: G~ = T^T G.
  std::vector<int> block_of(num_shell, -1);
  for (std::size_t i = 0; i < rotations.size(); ++i) {
    if (rotations[i].eq_a >= 0) block_of[rotations[i].eq_a] = static_cast<int>(i);
    if (rotations[i].eq_b >= 0) block_of[rotations[i].eq_b] = static_cast<int>(i);
  }
  rows_ = rows;
  for (ContactJacobianRow& row : rows_) {
    row.a = std::max({row.a, kCondensationFloor * row.b / kappa_, 1e-300});
    const int e = row.eq[3] >= 0 ? row.eq[3] : row.eq[4];
    if (e < 0 || block_of[e] < 0) continue;
    const Matrix2d& T = rotations[block_of[e]].T;
    const double ga = row.gradient[3], gb = row.gradient[4];
    row.gradient[3] = T(0, 0) * ga + T(1, 0) * gb;
    row.gradient[4] = T(0, 1) * ga + T(1, 1) * gb;
  }
  // Rows the factor has not seen (candidates appended since it was made) enter the
  // preconditioner uncondensed (b = 0): dlambda_i = r_i / a_i. A shorter set than the factor's
  // is not an appended one: it needs a new factor.
  if (has_preconditioner_ && pre_rows_.size() > rows_.size()) has_preconditioner_ = false;
  for (std::size_t i = pre_rows_.size(); has_preconditioner_ && i < rows_.size(); ++i) {
    pre_rows_.push_back(rows_[i]);
    pre_rows_.back().b = 0.0;
  }
  use_lu_ = false;
  ++preconditioner_age_;
  const bool stale = !has_preconditioner_ || last_products_ > kRefreshProducts ||
                     preconditioner_age_ > kMaxPreconditionerAge;
  if (stale && !refresh_preconditioner()) {
    factor_fallback(true);
    return;
  }
  if (border_ && !prepare_border()) factor_fallback(false);
}

bool ContactJacobianSolver::prepare_border() {
  const int n = static_cast<int>(J_->rows()) - 1;
  border_column_ = Eigen::VectorXd::Zero(n);
  border_row_ = Eigen::VectorXd::Zero(n);
  border_corner_ = 0;
  for (int c = 0; c <= n; ++c)
    for (SparseMatrix::InnerIterator it(*J_, c); it; ++it) {
      if (c == n && it.row() < n) border_column_[it.row()] = it.value();
      if (c < n && it.row() == n) border_row_[c] = it.value();
      if (c == n && it.row() == n) border_corner_ = it.value();
    }
  apply_condensed(border_column_, border_solution_);
  const double coupling = border_row_.dot(border_solution_);
  border_pivot_ = border_corner_ - coupling;
  return std::isfinite(border_pivot_) &&
         std::abs(border_pivot_) > 1e-12 * (std::abs(border_corner_) + std::abs(coupling));
}

void ContactJacobianSolver::forget_preconditioner() {
  lu_.forget();  // UMFPACK's symbolic analysis reads the values of the matrix it was made from
  has_preconditioner_ = false;
  preconditioner_age_ = 0;
  last_products_ = 0;
  coupled_.clear();
  pre_rotations_.clear();
  pre_rows_.clear();
}

void ContactJacobianSolver::apply_preconditioner(const Eigen::VectorXd& in,
                                                 Eigen::VectorXd& out) const {
  if (!border_) {
    apply_condensed(in, out);
    return;
  }
  const Eigen::Index n = in.size() - 1;
  Eigen::VectorXd inner;
  apply_condensed(in.head(n), inner);
  const double ya = (in[n] - border_row_.dot(inner)) / border_pivot_;
  out.resize(in.size());
  out.head(n) = inner - border_solution_ * ya;
  out[n] = ya;
}

void ContactJacobianSolver::apply_condensed(const Eigen::VectorXd& in, Eigen::VectorXd& out) const {
  const int nf = num_shell_;
  const int nr = static_cast<int>(pre_rows_.size());
  out.resize(in.size());
  // dlambda = M^-1 (r_lambda - B G~^T dx) with the shell's dx = S^-1 (T^T r_x + G~ M^-1 r_lambda)
  // (M diagonal but for the coupled rows, coupled_rows.hpp).
  coupled_.solve_rows(pre_rows_, in.data() + nf, out.data() + nf);
  Eigen::VectorXd r = in.head(nf);
  transpose_transform(pre_rotations_, r);
  for (int i = 0; i < nr; ++i) {
    const ContactJacobianRow& row = pre_rows_[static_cast<std::size_t>(i)];
    for (int k = 0; k < 5; ++k)
      if (row.eq[k] >= 0) r[row.eq[k]] += row.gradient[k] * out[nf + i];
  }
  Eigen::VectorXd y = factor_->solve(r);
  coupled_.correct_shell(y, *factor_);
  out.head(nf) = y;
  Eigen::VectorXd s(nr);
  for (int i = 0; i < nr; ++i) {
    const ContactJacobianRow& row = pre_rows_[static_cast<std::size_t>(i)];
    double gy = 0.0;
    for (int k = 0; k < 5; ++k)
      if (row.eq[k] >= 0) gy += row.gradient[k] * y[row.eq[k]];
    s[i] = in[nf + i] - row.b * gy;
  }
  coupled_.solve_rows(pre_rows_, s.data(), out.data() + nf);
}

Eigen::VectorXd ContactJacobianSolver::solve(const Eigen::VectorXd& rhs) {
  SI_REQUIRE(J_ != nullptr && rhs.size() == J_->rows(), "contact Jacobian: solve before factorize");
  // GMRES with the current factor; a stale factor that does not converge is refreshed once,
  // then the LU of J takes over for this linearisation.
  for (int attempt = 0; attempt < 2 && !use_lu_; ++attempt) {
    ++counters_.krylov_solves;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(rhs.size());
    const GmresResult r = gmres(
        [this](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
          out = (*J_) * in;
          coupling_.add_product(in, num_shell_, out);
        },
        [this](const Eigen::VectorXd& in, Eigen::VectorXd& out) { apply_preconditioner(in, out); },
        rhs, x, gmres_);
    counters_.krylov_products += r.iterations;
    last_products_ = r.iterations;
    if (r.converged && x.allFinite()) return x;
    char why[96];
    std::snprintf(why, sizeof why, "GMRES stopped after %d products at relative residual %.3g",
                  r.iterations, r.relative_residual);
    refresh_failure_ = why;
    if (preconditioner_age_ == 0 || !refresh_preconditioner()) break;
    if (border_ && !prepare_border()) break;
  }
  if (!use_lu_) factor_fallback(false);
  return lu_.solve(rhs);
}

}  // namespace si
