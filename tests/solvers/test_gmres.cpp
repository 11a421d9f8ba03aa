#include "solvers/gmres.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

namespace si {
namespace {

// A nonsymmetric, well-conditioned system (diagonal plus a scaled random part).
Eigen::MatrixXd test_matrix(int n) {
  std::srand(7);
  // Eigenvalues within about 0.2 n of n (circular law): away from 0, so restarts converge.
  return Eigen::MatrixXd::Identity(n, n) * n + Eigen::MatrixXd::Random(n, n) * (0.3 * std::sqrt(n));
}

LinearOperator dense(const Eigen::MatrixXd& A) {
  return [A](const Eigen::VectorXd& in, Eigen::VectorXd& out) { out = A * in; };
}

const LinearOperator kIdentity = [](const Eigen::VectorXd& in, Eigen::VectorXd& out) { out = in; };

// Reference: Householder QR of the same matrix (a different method).
TEST(Gmres, MatchesDenseSolveWithRestarts) {
  const Eigen::MatrixXd A = test_matrix(40);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(40, -1.0, 3.0);
  const Eigen::VectorXd reference = A.colPivHouseholderQr().solve(b);
  GmresSettings s;
  s.restart = 7;  // forces several restarts
  s.max_iterations = 400;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(40);
  const GmresResult r = gmres(dense(A), kIdentity, b, x, s);
  ASSERT_TRUE(r.converged);
  EXPECT_LE(r.relative_residual, s.relative_tolerance);
  EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm());
}

// With the exact inverse as preconditioner the Krylov space is exact after one product.
TEST(Gmres, ExactPreconditionerConvergesInOneProduct) {
  const Eigen::MatrixXd A = test_matrix(25);
  const Eigen::MatrixXd Ainv = A.inverse();
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(25);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(25);
  const GmresResult r = gmres(dense(A), dense(Ainv), b, x, {});
  ASSERT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 1);
}

// Without enough iterations it reports failure and the residual it reached.
TEST(Gmres, ReportsNonConvergence) {
  const Eigen::MatrixXd A = test_matrix(30);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(30);
  GmresSettings s;
  s.max_iterations = 3;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(30);
  const GmresResult r = gmres(dense(A), kIdentity, b, x, s);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_GT(r.relative_residual, s.relative_tolerance);
  EXPECT_NEAR(r.relative_residual, (b - A * x).norm() / b.norm(), 1e-12);
}

TEST(Gmres, ZeroRightHandSideGivesZero) {
  Eigen::VectorXd x = Eigen::VectorXd::Ones(5);
  const GmresResult r = gmres(dense(test_matrix(5)), kIdentity, Eigen::VectorXd::Zero(5), x, {});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(x.norm(), 0.0);
}

}  // namespace
}  // namespace si
