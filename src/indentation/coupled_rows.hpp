// Contact rows that read each other's multipliers (the elastic face: each gap carries
// sum_j C_ij lambda_j over its zone, elastic_face.hpp), eliminated exactly inside the condensed
// preconditioner of contact_jacobian_solver.hpp (row_coupling.hpp). With M the contact block of J
// (the rows' diagonals a_i and their couplings) and B = diag(b), eliminating the rows,
//     dlambda = M^-1 (r_lambda - B G~^T dx),
// leaves the shell with
//     S = H0 + G~_R W G~_R^T,   W = (M_RR)^-1 B_R - diag(b_R / a_R),
// where H0 is the factored matrix that condenses every row on its own diagonal and R the rows
// with couplings together with the rows they read that have b != 0 (the other rows' b vanish
// in M^-1 B, so off R the condensation on the diagonal is exact). S is solved by Woodbury's
// identity (Golub & Van Loan 2013, 2.1.4),
//     S^-1 = H0^-1 - Z W (I + G~_R^T Z W)^-1 G~_R^T H0^-1,   Z = H0^-1 G~_R,
// G~_R^T Z being |R| solves with H0's factor made as blocked solves, and Z c one more solve per
// application. Why: R is the contact patch,
// tens to hundreds of rows, while an LU of the whole J fills the zone's dense block into the
// shell's (measured on the paper's cap, 0 -> 10 mm: 8.8x the time of the same path without the
// law; docs/performance.md).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "core/sparse.hpp"
#include "indentation/contact_jacobian_row.hpp"
#include "indentation/row_coupling.hpp"
#include "solvers/linear_solver.hpp"

namespace si {

class CoupledRows {
 public:
  // The contact rows (num_shell shell rows before them in J; a floored, gradients in chart
  // coordinates, as the preconditioner condenses them) and their couplings. shell: H0's factor.
  // Returns false if M_RR or the Woodbury matrix is singular (the caller then factors J itself);
  // more rows than the correction pays for (kMaxCoupledRows) are left out (empty(): the rows
  // condense on their diagonals and GMRES carries the couplings).
  bool build(const RowCoupling& coupling, int num_shell,
             const std::vector<ContactJacobianRow>& rows, const LinearSolver& shell);
  bool empty() const { return index_.empty(); }
  void clear();
  // t = M^-1 r over the contact rows (rows appended since build(): b = 0, their diagonal).
  void solve_rows(const std::vector<ContactJacobianRow>& rows, const double* r, double* t) const;
  // y = H0^-1 rhs on entry, S^-1 rhs on exit (shell: H0's factor, as at build()).
  void correct_shell(Eigen::VectorXd& y, const LinearSolver& shell) const;

 private:
  struct Coupling {
    int row;     // place in R
    int column;  // contact row outside R
    double value;
  };
  std::vector<int> index_;                         // R: contact rows
  std::vector<Coupling> outside_;                  // M_RN
  Eigen::PartialPivLU<Eigen::MatrixXd> block_;     // M_RR
  SparseMatrix gradients_;                         // G~_R: num_shell x |R|
  Eigen::MatrixXd w_;                              // W
  Eigen::PartialPivLU<Eigen::MatrixXd> woodbury_;  // I + G~_R^T Z W
};

}  // namespace si
