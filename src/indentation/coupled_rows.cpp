#include "indentation/coupled_rows.hpp"

#include <algorithm>

namespace si {
namespace {

// The correction costs |R| solves with H0's factor per refresh (G~_R^T H0^-1 G~_R) and one more
// per GMRES product; what it saves is GMRES products. Beyond this many rows it costs more than it
// saves, and the rows condense on their diagonals, GMRES carrying the couplings. Measured
// (docs/performance.md, "Local contact laws"): with at most 36 rows (0.5 mm quarter cap, 0-2 mm)
// the correction takes the path from 1.8-2.0 s to 1.3-1.4 s; on the 0.25 mm quarter cap 0-10 mm
// (|R| up to 620), paired, all rows corrected 45-46 s, at most 800 the same, 400 40-42 s,
// 200 38-39 s, against 25-27 s without the law; an earlier pair put no correction at all
// with 200 (32-35 s against 31-34 s).
constexpr int kMaxCoupledRows = 200;
// G~_R^T H0^-1 G~_R is made this many columns of H0^-1 G~_R at a time (a blocked solve of
// num_shell x kSolveColumns), so that Z is never held whole.
constexpr int kSolveColumns = 64;
// Below this reciprocal condition estimate M_RR or I + G~^T Z W is taken as singular (as the
// sparse solvers' kSingularRcond).
constexpr double kSingularBlock = 1e-14;

}  // namespace

void CoupledRows::clear() {
  index_.clear();
  outside_.clear();
  gradients_.resize(0, 0);
  w_.resize(0, 0);
}

namespace {

// G~_R: num_shell x |R|, column k the chart gradient of row index[k].
SparseMatrix chart_gradients(int num_shell, const std::vector<ContactJacobianRow>& rows,
                             const std::vector<int>& index) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (int k = 0; k < static_cast<int>(index.size()); ++k) {
    const ContactJacobianRow& row = rows[index[k]];
    for (int l = 0; l < 5; ++l)
      if (row.eq[l] >= 0) t.emplace_back(row.eq[l], k, row.gradient[l]);
  }
  SparseMatrix G(num_shell, static_cast<Eigen::Index>(index.size()));
  G.setFromTriplets(t.begin(), t.end());
  return G;
}

// G^T H0^-1 G, kSolveColumns columns of H0^-1 G at a time.
Eigen::MatrixXd projected_inverse(const SparseMatrix& G, const LinearSolver& shell) {
  const int r = static_cast<int>(G.cols());
  Eigen::MatrixXd out(r, r);
  for (int first = 0; first < r; first += kSolveColumns) {
    const int n = std::min(kSolveColumns, r - first);
    const SparseMatrix block = G.middleCols(first, n);
    out.middleCols(first, n) = G.transpose() * shell.solve_columns(Eigen::MatrixXd(block));
  }
  return out;
}

}  // namespace

bool CoupledRows::build(const RowCoupling& coupling, int num_shell,
                        const std::vector<ContactJacobianRow>& rows, const LinearSolver& shell) {
  clear();
  if (coupling.empty() || coupling.scale.isZero(0.0)) return true;
  // R: the members that read the others (their b != 0, a pressed row's), with the members they
  // read whose rows have b != 0; the other members (b = 0) stay outside R, read through M_RN.
  const int m = static_cast<int>(coupling.members.size());
  std::vector<int> in_r, outside;  // places among the members
  for (int p = 0; p < m; ++p)
    (coupling.scale[p] != 0.0 || rows[coupling.members[p]].b != 0.0 ? in_r : outside).push_back(p);
  const int r = static_cast<int>(in_r.size());
  if (r > kMaxCoupledRows) return true;
  for (int p : in_r) index_.push_back(coupling.members[p]);

  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(r, r);
  Eigen::VectorXd b(r), b_over_a(r);
  for (int k = 0; k < r; ++k) {
    const ContactJacobianRow& row = rows[index_[k]];
    M(k, k) = row.a;
    b[k] = row.b;
    b_over_a[k] = row.b / row.a;
    if (coupling.scale[in_r[k]] == 0.0) continue;
    for (int l = 0; l < r; ++l)
      if (l != k) M(k, l) = coupling.entry(in_r[k], in_r[l]);
    for (int q : outside) outside_.push_back({k, coupling.members[q], coupling.entry(in_r[k], q)});
  }
  block_.compute(M);
  if (block_.rcond() > kSingularBlock) {
    w_ = block_.solve(Eigen::MatrixXd(b.asDiagonal()));
    w_.diagonal() -= b_over_a;
    gradients_ = chart_gradients(num_shell, rows, index_);
    woodbury_.compute(Eigen::MatrixXd::Identity(r, r) + projected_inverse(gradients_, shell) * w_);
    if (woodbury_.rcond() > kSingularBlock) return true;
  }
  clear();
  return false;
}

void CoupledRows::solve_rows(const std::vector<ContactJacobianRow>& rows, const double* r,
                             double* t) const {
  Eigen::VectorXd v(static_cast<Eigen::Index>(index_.size()));
  for (int k = 0; k < static_cast<int>(index_.size()); ++k) v[k] = r[index_[k]];
  for (std::size_t i = 0; i < rows.size(); ++i) t[i] = r[i] / rows[i].a;
  if (empty()) return;
  for (const Coupling& c : outside_) v[c.row] -= c.value * t[c.column];
  v = block_.solve(v);
  for (int k = 0; k < static_cast<int>(index_.size()); ++k) t[index_[k]] = v[k];
}

// Z c = H0^-1 (G~_R c): one more solve instead of Z's num_shell x |R| product (memory-bound:
// 116 MB read per GMRES product with 800 coupled rows on a 0.25 mm apex mesh).
void CoupledRows::correct_shell(Eigen::VectorXd& y, const LinearSolver& shell) const {
  if (empty()) return;
  const Eigen::VectorXd u = gradients_.transpose() * y;
  y -= shell.solve(gradients_ * (w_ * woodbury_.solve(u)));
}

}  // namespace si
