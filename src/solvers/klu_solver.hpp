// Sparse LU (KLU through Eigen) for general matrices, e.g. the unsymmetric, indefinite contact
// Jacobian (indentation/indentation_problem.hpp). KLU (Davis & Palamadai Natarajan 2010) keeps the
// symbolic analysis across factorize(); it uses no BLAS, so it is not sped up by OpenBLAS as
// UMFPACK is. docs/performance.md compares the two on the contact Jacobian.
#pragma once

#include <memory>

#include "solvers/linear_solver.hpp"

namespace si {

class KluSolver : public LinearSolver {
 public:
  KluSolver();
  ~KluSolver() override;
  LinearSolverKind kind() const override { return LinearSolverKind::kKlu; }
  std::string name() const override { return "klu"; }
  bool needs_spd() const override { return false; }
  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  double rcond() const override { return rcond_; }

 private:
  struct Impl;  // keeps klu.h out of this header
  std::unique_ptr<Impl> impl_;
  double rcond_ = 0;
};

}  // namespace si
