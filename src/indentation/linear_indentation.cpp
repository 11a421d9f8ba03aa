#include "indentation/linear_indentation.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <limits>

#include "core/error.hpp"

namespace si {

LinearIndentation::LinearIndentation(const IndentationProblem& problem) : problem_(problem) {
  SI_REQUIRE(problem.model().kinematics == Kinematics::kLinear,
             "the linear fast path needs linear kinematics");
  SI_REQUIRE(problem.num_local_unknowns() == 0,
             "the linear fast path cannot carry a power-law local contact (it is nonlinear)");
  factor();
  C_ = problem.contact_matrix();
  Ct_ = C_.transpose();
  g0_ = problem.reference_gaps();
  columns_.resize(num_candidates());
  lambda_ = Eigen::VectorXd::Zero(num_candidates());
}

LinearIndentation::~LinearIndentation() = default;

LinearSolver& LinearIndentation::factor() {
  if (!solver_) {
    solver_ = make_linear_solver(LinearSolverKind::kCholmod);
    const SparseMatrix& K = problem_.linear_tangent();
    solver_->analyze(K);
    solver_->factorize(K);
  }
  return *solver_;
}

void LinearIndentation::make_columns(const std::vector<int>& needed) {
  std::vector<int> missing;
  for (int j : needed)
    if (columns_[j].size() == 0) missing.push_back(j);
  const int n = static_cast<int>(Ct_.rows());
  for (std::size_t first = 0; first < missing.size(); first += kColumnBlock) {
    const int m = static_cast<int>(std::min(kColumnBlock, missing.size() - first));
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, m);
    for (int k = 0; k < m; ++k) B.col(k) = Ct_.col(missing[first + k]);
    const Eigen::MatrixXd X = factor().solve_columns(B);
    for (int k = 0; k < m; ++k) {
      const int j = missing[first + k];
      columns_[j] = C_ * X.col(k);
      // A linear local law's share: c_L++ / A_j (vam) or the elastic face's coefficients.
      problem_.add_local_compliance_column(j, columns_[j]);
    }
  }
}

const Eigen::VectorXd& LinearIndentation::column(int j) {
  if (columns_[j].size() == 0) make_columns({j});
  return columns_[j];
}

Eigen::VectorXd LinearIndentation::times(const Eigen::VectorXd& lambda) {
  std::vector<int> nonzero;
  for (int j = 0; j < num_candidates(); ++j)
    if (lambda[j] != 0) nonzero.push_back(j);
  make_columns(nonzero);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(num_candidates());
  for (int j : nonzero) y += lambda[j] * columns_[j];
  return y;
}

Eigen::VectorXd LinearIndentation::minimiser_on(const Eigen::VectorXd& q,
                                                const std::vector<int>& free) {
  const int m = static_cast<int>(free.size());
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(q.size());
  if (m == 0) return lambda;
  make_columns(free);
  Eigen::MatrixXd Sff(m, m);
  Eigen::VectorXd qf(m);
  for (int b = 0; b < m; ++b) {
    qf[b] = q[free[b]];
    const Eigen::VectorXd& c = column(free[b]);
    for (int a = 0; a < m; ++a) Sff(a, b) = c[free[a]];
  }
  // S is symmetric up to the solver's round-off; the dense Cholesky wants it exactly.
  Sff = 0.5 * (Sff + Sff.transpose()).eval();
  const Eigen::VectorXd sol = Sff.llt().solve(-qf);
  for (int a = 0; a < m; ++a) lambda[free[a]] = sol[a];
  return lambda;
}

// The primal-dual active-set method (Hintermueller, Ito & Kunisch 2002) from the warm start:
// usually two or three dense solves per depth, as all contact changes are taken at once. It
// can cycle on matrices that are not M-matrices; then the primal active-set method below, which
// terminates finitely, takes over from the same warm start.
bool LinearIndentation::solve_pdas(const Eigen::VectorXd& q, double tol, Eigen::VectorXd& lambda) {
  const int nc = static_cast<int>(q.size());
  Eigen::VectorXd w = q + times(lambda_);
  std::vector<int> set;
  for (int i = 0; i < nc; ++i)
    if (lambda_[i] > w[i]) set.push_back(i);
  for (int k = 0; k < 20; ++k) {
    ++iterations_;
    lambda = minimiser_on(q, set);
    w = q + times(lambda);
    std::vector<int> next;
    for (int i = 0; i < nc; ++i)
      if (lambda[i] > w[i]) next.push_back(i);
    if (next == set)
      return lambda.minCoeff() >= -tol * (1 + lambda.cwiseAbs().maxCoeff()) &&
             (w.array() >= -tol).all();
    set = next;
  }
  return false;
}

cont::Vector LinearIndentation::solve(double h) {
  const Eigen::VectorXd lambda = multipliers(h);
  const Eigen::VectorXd x = factor().solve(C_.transpose() * lambda);
  cont::Vector z(x.size() + lambda.size());
  z << x, lambda;
  return z;
}

Eigen::VectorXd LinearIndentation::multipliers(double h) {
  const int nc = num_candidates();
  const Eigen::VectorXd q = g0_ - Eigen::VectorXd::Constant(nc, h);
  // Optimality tolerance on w: roundoff of S lambda, relative to the gap scale.
  const double tol = 1e-13 * std::max(1.0, q.cwiseAbs().maxCoeff());
  iterations_ = 0;
  Eigen::VectorXd lambda;
  if (!solve_pdas(q, tol, lambda)) solve_primal(q, tol, lambda);
  lambda = lambda.cwiseMax(0.0);
  lambda_ = lambda;
  return lambda;
}

// The primal active-set method for the convex QP (Nocedal & Wright 2006, Alg. 16.3).
void LinearIndentation::solve_primal(const Eigen::VectorXd& q, double tol,
                                     Eigen::VectorXd& lambda) {
  const int nc = static_cast<int>(q.size());
  lambda = lambda_;
  std::vector<int> free;  // the working set's complement: indices where lambda may be > 0
  for (int i = 0; i < nc; ++i)
    if (lambda[i] > 0) free.push_back(i);
  const int max_iterations = 10 * nc + 10;
  for (int k = 0;; ++k, ++iterations_) {
    if (k > max_iterations)
      throw_numerical("linear contact: the active-set method did not terminate");
    const Eigen::VectorXd target = minimiser_on(q, free);
    // Blocked by a bound: step to the first multiplier reaching zero and drop it.
    double alpha = 1.0;
    int blocking = -1;
    for (int i : free)
      if (target[i] < 0 && lambda[i] - target[i] > 0) {
        const double a = lambda[i] / (lambda[i] - target[i]);
        if (a < alpha) alpha = a, blocking = i;
      }
    lambda += alpha * (target - lambda);
    if (blocking >= 0) {
      lambda[blocking] = 0;
      free.erase(std::find(free.begin(), free.end(), blocking));
      continue;
    }
    // Optimal on this set: free the most violated gap, if any.
    const Eigen::VectorXd w = q + times(lambda);
    int entering = -1;
    double most = -tol;
    for (int i = 0; i < nc; ++i)
      if (lambda[i] == 0 && w[i] < most && std::find(free.begin(), free.end(), i) == free.end())
        most = w[i], entering = i;
    if (entering < 0) return;
    free.push_back(entering);
  }
}

}  // namespace si
