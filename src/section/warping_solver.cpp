#include "section/warping_solver.hpp"

#include <string>

#include "core/error.hpp"

namespace si {
namespace {

Eigen::MatrixXd bordered_matrix(const Eigen::MatrixXd& E, const Eigen::MatrixXd& H_psi) {
  const Eigen::Index n = E.rows();
  const Eigen::Index c = H_psi.cols();
  const double s = E.diagonal().cwiseAbs().maxCoeff();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + c, n + c);
  K.topLeftCorner(n, n) = E;
  K.topRightCorner(n, c) = s * H_psi;
  K.bottomLeftCorner(c, n) = s * H_psi.transpose();
  return K;
}

}  // namespace

WarpingSolver::WarpingSolver(const Eigen::MatrixXd& E, const Eigen::MatrixXd& H_psi)
    : n_(E.rows()), lu_(bordered_matrix(E, H_psi)) {
  // The bordered matrix is regular whenever every ply stiffness is positive definite; a
  // reciprocal condition number at round-off level means it is not.
  const double rcond = lu_.rcond();
  if (!(rcond > 1e3 * Eigen::NumTraits<double>::epsilon()))
    throw_numerical(
        "the constrained warping system of the VAM section analysis is singular "
        "(reciprocal condition number " +
        std::to_string(rcond) + ")");
}

Eigen::MatrixXd WarpingSolver::solve(const Eigen::MatrixXd& r) const {
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(lu_.rows(), r.cols());
  rhs.topRows(n_) = -r;
  return lu_.solve(rhs).topRows(n_);
}

}  // namespace si
