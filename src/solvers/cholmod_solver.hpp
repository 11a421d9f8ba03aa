// Supernodal sparse Cholesky (CHOLMOD through Eigen) for symmetric positive-definite tangents.
// The symbolic analysis (fill-reducing ordering, supernodes) is done once in analyze();
// factorize() reuses it. A matrix that is not positive definite (a free body, or a state past a
// limit point) throws a numerical error; the static solver then falls back to UMFPACK.
#pragma once

#include <memory>
#include <string>

#include "solvers/linear_solver.hpp"

namespace si {

class CholmodSolver : public LinearSolver {
 public:
  CholmodSolver();
  ~CholmodSolver() override;
  LinearSolverKind kind() const override { return LinearSolverKind::kCholmod; }
  std::string name() const override { return "cholmod"; }
  bool needs_spd() const override { return true; }
  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd& B) const override;
  double rcond() const override { return rcond_; }
  bool out_of_memory() const override { return out_of_memory_; }

 private:
  struct Impl;  // keeps cholmod.h out of this header
  std::string failure_message(const SparseMatrix& A) const;
  std::unique_ptr<Impl> impl_;
  double rcond_ = 0;
  bool out_of_memory_ = false;
};

}  // namespace si
