// Sparse LDL' without pivoting (Eigen's SimplicialLDLT, AMD ordering) for symmetric matrices that
// need not be positive definite: P A P' = L D L' with D diagonal of either sign exists wherever no
// leading pivot of the ordered matrix vanishes, the practice of structural codes past a limit
// point (the "negative pivots" of a stiffness factorization; Golub & Van Loan 2013, 4.1-4.2).
// Without pivoting it is not backward stable for every indefinite matrix: a caller uses it as a
// preconditioner (GMRES solves the system itself) or checks its residual. Eigen's simplicial
// LDL' took 5.8 times CHOLMOD's supernodal Cholesky on a plate-like 6-dof stencil of 1e5 unknowns
// (continuation/cholmod_factorization.hpp), so it is for where that Cholesky fails. Reads the
// lower triangle. Not cont::SparseLdlt (continuation/inertia.hpp), the stability analysis's
// factorization of the same kind: that one factors a copy K - sigma I anew each time and moves a
// zero pivot's shift to keep a factor, where a linear solver reuses its analysis and must say
// that the matrix is singular.
#pragma once

#include <memory>

#include "solvers/linear_solver.hpp"

namespace si {

class LdltSolver : public LinearSolver {
 public:
  LdltSolver();
  ~LdltSolver() override;
  LinearSolverKind kind() const override { return LinearSolverKind::kLdlt; }
  std::string name() const override { return "ldlt"; }
  bool needs_spd() const override { return false; }
  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  double rcond() const override { return rcond_; }
  bool out_of_memory() const override { return out_of_memory_; }
  // D's negative entries at the last factorization: the eigenvalues of A below zero (Sylvester).
  int negative_pivots() const { return negative_pivots_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double rcond_ = 0;
  bool out_of_memory_ = false;
  int negative_pivots_ = 0;
};

}  // namespace si
