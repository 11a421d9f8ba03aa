// Sparse LU (UMFPACK through Eigen) for general, e.g. non-symmetric (follower pressure) or
// indefinite (past a limit point), tangents. The symbolic analysis is kept across factorize().
#pragma once

#include <memory>

#include "solvers/linear_solver.hpp"

namespace si {

class UmfpackSolver : public LinearSolver {
 public:
  UmfpackSolver();
  ~UmfpackSolver() override;
  LinearSolverKind kind() const override { return LinearSolverKind::kUmfpack; }
  std::string name() const override { return "umfpack"; }
  bool needs_spd() const override { return false; }
  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  double rcond() const override { return rcond_; }
  bool out_of_memory() const override { return out_of_memory_; }

 private:
  struct Impl;  // keeps umfpack.h out of this header
  std::unique_ptr<Impl> impl_;
  double rcond_ = 0;
  bool out_of_memory_ = false;
};

}  // namespace si
