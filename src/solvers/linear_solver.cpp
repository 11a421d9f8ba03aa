#include "solvers/linear_solver.hpp"

#include <sstream>

#include "core/error.hpp"
#include "solvers/cholmod_solver.hpp"
#include "solvers/klu_solver.hpp"
#include "solvers/ldlt_solver.hpp"
#include "solvers/umfpack_solver.hpp"

namespace si {

std::unique_ptr<LinearSolver> make_linear_solver(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::kCholmod:
      return std::make_unique<CholmodSolver>();
    case LinearSolverKind::kUmfpack:
      return std::make_unique<UmfpackSolver>();
    case LinearSolverKind::kKlu:
      return std::make_unique<KluSolver>();
    case LinearSolverKind::kLdlt:
      return std::make_unique<LdltSolver>();
  }
  throw Error(ErrorKind::kInternal, "make_linear_solver: unknown solver kind");
}

Eigen::MatrixXd LinearSolver::solve_columns(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X(B.rows(), B.cols());
  for (Eigen::Index c = 0; c < B.cols(); ++c) X.col(c) = solve(B.col(c));
  return X;
}

std::string singular_matrix_message(const std::string& solver, double rcond) {
  std::ostringstream os;
  os << "stiffness matrix is singular (" << solver << ", pivot ratio " << rcond
     << "): the model may be insufficiently supported (free rigid-body motion)";
  return os.str();
}

}  // namespace si
