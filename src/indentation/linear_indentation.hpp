// The linear fast path (paper eqs 77-80): with linear kinematics and the linearised gap
// g = g0 - h + C x (indentation_problem.hpp), K is factored once and the contact problem at each
// depth condenses onto the candidates (the Schur complement; the paper's K_mod = -S):
//     lambda >= 0,   w = g0 - h + S lambda >= 0,   lambda . w = 0,   S = C K^-1 C^T,
// an LCP with S symmetric positive definite, i.e. the convex QP
//     min 1/2 lambda^T S lambda + (g0 - h)^T lambda   subject to lambda >= 0.
// It is solved by the primal-dual active-set method warm-started from the previous depth (all
// contact changes at once, a few dense solves), with the primal active-set method (Nocedal &
// Wright 2006, Alg. 16.3), which terminates finitely, as the fall-back; then x = K^-1 C^T lambda.
// S is never formed whole: its column j (one sparse solve; those entering together in blocks of
// one multi-right-hand-side solve) is computed the first time candidate j enters a contact set
// and kept, so the cost and memory follow the contact zone, not the candidates (a 1e6-unknown
// cap has 57,000 candidates: a dense S would take 26 GB and 57,000 solves). Each depth costs a few
// small dense Cholesky solves and one sparse back-substitution.
#pragma once

#include <memory>
#include <vector>

#include "indentation/indentation_problem.hpp"

namespace si {

class LinearIndentation {
 public:
  // The problem must have linear kinematics; it is kept by reference.
  explicit LinearIndentation(const IndentationProblem& problem);
  ~LinearIndentation();

  // The problem's unknowns z = [x ; lambda] at depth h.
  cont::Vector solve(double h);
  // lambda alone (what the force needs): solve(h) without its back-substitution for x.
  Eigen::VectorXd multipliers(double h);
  int last_iterations() const { return iterations_; }  // dense solves at the last depth
  // Frees K's factor (234 MB with CHOLMOD's workspace on the 1e5-unknown cap) until a solve
  // needs it again: then it is factored anew, to the same bits (CHOLMOD is deterministic). The S
  // columns computed so far are kept, so depths whose contact sets need no new column never
  // refactor.
  void release_factor() { solver_.reset(); }
  bool holds_factor() const { return solver_ != nullptr; }

 private:
  int num_candidates() const { return static_cast<int>(C_.rows()); }
  // Column j of S, computed on first use.
  const Eigen::VectorXd& column(int j);
  // The columns of `needed` not computed yet, by blocked solves of kColumnBlock right-hand sides
  // (one pass over the factor per block, BLAS-3, where single solves take one per column).
  void make_columns(const std::vector<int>& needed);
  // 32 right-hand sides and their solutions: 0.5 GB on the 1e6-unknown cap, beside its 13 GB.
  static constexpr std::size_t kColumnBlock = 32;
  // S lambda from the columns of lambda's nonzeros.
  Eigen::VectorXd times(const Eigen::VectorXd& lambda);
  // lambda on the set `free` (others zero) minimising the QP there: S_FF lambda_F = -q_F.
  Eigen::VectorXd minimiser_on(const Eigen::VectorXd& q, const std::vector<int>& free);
  bool solve_pdas(const Eigen::VectorXd& q, double tol, Eigen::VectorXd& lambda);
  void solve_primal(const Eigen::VectorXd& q, double tol, Eigen::VectorXd& lambda);
  // K's factor, made when first needed (again after release_factor()).
  LinearSolver& factor();
  const IndentationProblem& problem_;
  std::unique_ptr<LinearSolver> solver_;
  SparseMatrix C_;
  SparseMatrix Ct_;
  std::vector<Eigen::VectorXd> columns_;  // S's columns computed so far (empty: not yet)
  Eigen::VectorXd g0_;
  Eigen::VectorXd lambda_;  // warm start
  int iterations_ = 0;
};

}  // namespace si
