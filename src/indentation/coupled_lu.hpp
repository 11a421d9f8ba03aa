// A sparse LU of the indentation Jacobian with its contact rows' couplings (row_coupling.hpp)
// assembled in: the direct solvers' route and the Krylov solver's fallback. Its symbolic
// analysis is kept across factorizations while J's pattern (forget() when it changes) and the
// couplings' rows stay the same; the couplings follow the elastic face's zone, which may widen
// with J's pattern unchanged.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "core/sparse.hpp"
#include "indentation/row_coupling.hpp"
#include "solvers/linear_solver.hpp"

namespace si {

class CoupledLu {
 public:
  explicit CoupledLu(LinearSolverKind kind) : make_([kind] { return make_linear_solver(kind); }) {}
  explicit CoupledLu(LinearSolverFactory make) : make_(std::move(make)) {}
  // The next factorize() analyses anew (J's pattern changed, or a new solver's solves are
  // wanted bit for bit: UMFPACK's analysis reads the values it was made from).
  void forget() { lu_.reset(); }
  // J (the contact rows from `first`) plus `coupling`. Throws a numerical error if singular.
  void factorize(const SparseMatrix& J, int first, const RowCoupling& coupling);
  // After factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const { return lu_->solve(rhs); }
  // The last factorize() failed for lack of memory (LinearSolver::out_of_memory).
  bool out_of_memory() const { return lu_ && lu_->out_of_memory(); }

 private:
  LinearSolverFactory make_;
  std::unique_ptr<LinearSolver> lu_;
  std::vector<int> members_;  // the couplings' rows lu_'s analysis was made with
  SparseMatrix coupled_;      // J with the couplings
};

}  // namespace si
