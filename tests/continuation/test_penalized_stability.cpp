// Stability from a penalised factorization (penalized_stability.hpp) against the dense restricted
// tangent Z_d' K Z_d (Z_d from an SVD of A): the eigenvalues within the Schur-complement bound
// ||K_zy||^2 / (rho lambda_min(B)) and never above the exact ones, the error falling as 1/rho; and
// what it must not report: a restricted tangent with a negative eigenvalue never has a positive
// definite penalised matrix (so the fast route cannot call an unstable point stable).
#include <gtest/gtest.h>

#include <cmath>

#include "continuation/cholmod_factorization.hpp"
#include "continuation/penalized_stability.hpp"
#include "random_sparse.hpp"

namespace si::cont {
namespace {

constexpr int kNodes = 70;
constexpr int kDofs = 3;
constexpr int kN = kNodes * kDofs;

SparseMatrix constraints() {
  return test::node_constraints({1, 9, 10, 30, 44, 45, 68}, kDofs, kN, 5);
}

SparseMatrix penalized(const SparseMatrix& K, const SparseMatrix& A, double rho) {
  return SparseMatrix(K + rho * SparseMatrix(SparseMatrix(A.transpose()) * A));
}

// K0 shifted so that the restricted tangent's lowest eigenvalue is `lowest`.
SparseMatrix shifted_to(const SparseMatrix& K0, const Matrix& Zd, double lowest) {
  const double shift = test::dense_eigenvalues(Zd.transpose() * Matrix(K0) * Zd)(0) - lowest;
  SparseMatrix K = K0;
  for (int i = 0; i < kN; ++i) K.coeffRef(i, i) -= shift;
  return K;
}

// ||K_zy||^2 / (rho lambda_min(B)): Y an orthonormal basis of range(A'), B = Y'A'AY.
double schur_bound(const SparseMatrix& K, const SparseMatrix& A, const Matrix& Zd, double rho) {
  const Eigen::JacobiSVD<Matrix> svd(Matrix(A), Eigen::ComputeFullV);
  const Matrix Y = svd.matrixV().leftCols(A.rows());
  const Vector b = test::dense_eigenvalues(Y.transpose() * Matrix(A).transpose() * Matrix(A) * Y);
  const double kzy = (Zd.transpose() * Matrix(K) * Y).operatorNorm();
  return kzy * kzy / (rho * b(0));
}

bool stability_by_penalty(const SparseMatrix& K, const SparseMatrix& A, double rho, int modes,
                          Stability& out) {
  CholmodFirstFactorization f;
  if (!f.factorize(penalized(K, A, rho), 0.0) || !f.positive_definite()) return false;
  const PenalizedSolve solve = [&f](const Vector& in, Vector& y) {
    y.resize(in.size());
    f.solve(in.data(), y.data());
  };
  return stability_from_penalized(solve, A, K.rows(), modes, EigenOptions{}, out);
}

TEST(PenalizedStability, EigenvaluesWithinTheSchurBoundBelowTheExactOnes) {
  const SparseMatrix A = constraints();
  const Matrix Zd = test::dense_null_space(A);
  // Lowest restricted eigenvalue 0.5 on a K made indefinite along the constrained directions
  // (-50 A'A leaves Z'KZ alone): the constraints are what make it stable.
  const SparseMatrix K0 = test::random_symmetric(kNodes, kDofs, 0.0, 13);
  const SparseMatrix K = penalized(shifted_to(K0, Zd, 0.5), A, -50.0);
  ASSERT_LT(test::dense_eigenvalues(Matrix(K))(0), 0.0);
  const Vector exact = test::dense_eigenvalues(Zd.transpose() * Matrix(K) * Zd);
  const int modes = 4;
  double previous = 0.0;
  for (double rho : {1e4, 1e5, 1e6}) {
    Stability s;
    ASSERT_TRUE(stability_by_penalty(K, A, rho, modes, s)) << rho;
    EXPECT_EQ(s.negative, 0);
    const double bound = schur_bound(K, A, Zd, rho);
    double error = 0.0;
    for (int j = 0; j < modes; ++j) {
      EXPECT_LE(s.eigenvalues(j), exact(j) + 1e-10) << j;  // conservative
      EXPECT_GE(s.eigenvalues(j), exact(j) - bound - 1e-10) << j;
      error = std::max(error, exact(j) - s.eigenvalues(j));
      const Vector& v = s.modes[static_cast<std::size_t>(j)];
      EXPECT_NEAR(v.norm(), 1.0, 1e-12);
      EXPECT_LT((Matrix(A) * v).norm(), 1e-12);  // the mode keeps the constraints
    }
    // The error falls as 1/rho (the leading term of the Schur complement's series).
    if (previous > 0) {
      EXPECT_NEAR(previous / error, 10.0, 0.5) << rho;
    }
    previous = error;
  }
}

TEST(PenalizedStability, WithoutConstraintsTheEigenvaluesAreExact) {
  const SparseMatrix K = test::random_symmetric(kNodes, kDofs, -2.0, 29);
  const Vector exact = test::dense_eigenvalues(Matrix(K));
  ASSERT_GT(exact(0), 0.0);
  Stability s;
  ASSERT_TRUE(stability_by_penalty(K, SparseMatrix(0, kN), 1e6, 3, s));
  for (int j = 0; j < 3; ++j) EXPECT_NEAR(s.eigenvalues(j), exact(j), 1e-10 * exact(j)) << j;
}

// What must not be reported: with a negative restricted eigenvalue, however large rho, the
// penalised matrix is not positive definite (v'Pv = v'Kv < 0 for v in null(A)), so the caller
// never takes the fast route; a zero one likewise is never called stable.
TEST(PenalizedStability, UnstableRestrictedTangentNeverGivesAPositiveDefinitePenalty) {
  const SparseMatrix A = constraints();
  const Matrix Zd = test::dense_null_space(A);
  const SparseMatrix K0 = test::random_symmetric(kNodes, kDofs, 0.0, 13);
  for (double lowest : {-1e-6, -0.5, -5.0})
    for (double rho : {1e4, 1e8, 1e12}) {
      Stability s;
      EXPECT_FALSE(stability_by_penalty(shifted_to(K0, Zd, lowest), A, rho, 1, s))
          << lowest << " " << rho;
    }
}

// Too small a restricted space for Lanczos: refused, the caller analyses it densely.
TEST(PenalizedStability, TinyRestrictedSpaceIsLeftToTheDirectAnalysis) {
  const SparseMatrix K = test::random_symmetric(10, 3, -2.0, 31);
  const SparseMatrix A = test::node_constraints({1, 4}, 3, 30, 7);
  Stability s;
  EXPECT_FALSE(stability_by_penalty(K, A, 1e6, 1, s));
}

}  // namespace
}  // namespace si::cont
