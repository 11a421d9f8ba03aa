#include "section/reduced_stiffness.hpp"

#include "core/error.hpp"

namespace si {

Matrix3d reduced_stiffness_yu(const Matrix6d& C_yu) {
  const Eigen::LLT<Matrix6d> llt(C_yu);
  if (llt.info() != Eigen::Success)
    throw_numerical("ply stiffness is not positive definite; cannot condense to plane stress");
  const Matrix6d S = llt.solve(Matrix6d::Identity());
  const Matrix3d Q = S.topLeftCorner<3, 3>().inverse();
  return 0.5 * (Q + Q.transpose());
}

Matrix3d reduced_stiffness(const Ply& ply) {
  return reduced_stiffness_yu(ply.stiffness_yu());
}

}  // namespace si
