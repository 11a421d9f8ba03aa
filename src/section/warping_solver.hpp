// The single linear-algebra kernel of the VAM section analysis (shared/docs/vam.md 4.3):
//   minimise 1/2 V^T E V + V^T r  subject to  (H psi)^T V = 0   (thickness-average warping zero)
// through the bordered (KKT) system
//   [ E          s H psi ] [V     ]   [ -r ]
//   [ s (H psi)^T   0    ] [lambda] = [  0 ],    s = max |diag E|,
// factored once and reused for every right-hand side. The scaling s only balances the blocks
// (without it mm/MPa data lose 6-8 digits); the multiplier is lambda = -psi^T r / s, a uniform
// "body force" balancing the part of r with a non-zero resultant.
#pragma once

#include <Eigen/Dense>

namespace si {

class WarpingSolver {
 public:
  // E: n x n symmetric positive semi-definite with the rigid translations as kernel;
  // H_psi: n x 3. Throws a numerical si::Error if the bordered matrix is singular.
  WarpingSolver(const Eigen::MatrixXd& E, const Eigen::MatrixXd& H_psi);

  // The warping part V (n x k) for the k right-hand sides r (n x k).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& r) const;

 private:
  Eigen::Index n_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace si
