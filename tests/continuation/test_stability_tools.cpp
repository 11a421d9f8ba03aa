// The stability tools against dense eigen-solves of the same matrices: the inertia of an LDL'
// (Sylvester), the lowest eigenpairs by shift-invert Lanczos (Spectra), the null space of
// constraint rows by local Householder reflections and the restricted tangent Z'KZ.
// Reference: Eigen's dense SelfAdjointEigenSolver (tridiagonal QR), and for the null space a
// dense SVD of A, so the reduced spectrum is compared on two independently built bases.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../verification_record.hpp"
#include "continuation/cholmod_factorization.hpp"
#include "continuation/constraint_null_space.hpp"
#include "continuation/stability_analysis.hpp"
#include "random_sparse.hpp"

namespace si::cont {
namespace {

int count_below(const Vector& values, double x) {
  return static_cast<int>((values.array() < x).count());
}

// Relative error of the computed lowest eigenvalues against the dense ones.
double max_relative_error(const Vector& computed, const Vector& dense) {
  double e = 0.0;
  for (Eigen::Index i = 0; i < computed.size(); ++i)
    e = std::max(e, std::abs(computed(i) - dense(i)) / std::abs(dense(i)));
  return e;
}

// Shifts that put 0, 3 and 12 eigenvalues of the test matrix below zero, each in the middle of a
// gap of the dense spectrum (so that relative accuracy is meaningful).
std::vector<double> shifts_for(const Vector& spectrum, std::initializer_list<int> negatives) {
  std::vector<double> out;
  for (int k : negatives)
    out.push_back(k == 0 ? spectrum(0) - 1.0 : 0.5 * (spectrum(k - 1) + spectrum(k)));
  return out;
}

TEST(ContInertia, NegativeCountMatchesDenseEigenvalues) {
  const SparseMatrix K0 = test::random_symmetric(80, 3, 0.0, 7);
  const Vector spectrum = test::dense_eigenvalues(Matrix(K0));
  for (double shift : shifts_for(spectrum, {0, 1, 3, 12, 100})) {
    SparseLdlt ldlt;
    ASSERT_TRUE(ldlt.factorize(K0, shift));
    EXPECT_EQ(ldlt.inertia().negative, count_below(spectrum, shift)) << "shift " << shift;
    EXPECT_EQ(ldlt.inertia().zero, 0);
    EXPECT_EQ(ldlt.inertia().negative + ldlt.inertia().positive, 240);
  }
}

TEST(ContInertia, ExactZeroPivotCountedAsZero) {
  // diag(2, 0, -1, 3): the zero pivot stops the LDL'; the two shifted factorizations count it.
  SparseMatrix K(4, 4);
  K.insert(0, 0) = 2.0;
  K.insert(1, 1) = 0.0;
  K.insert(2, 2) = -1.0;
  K.insert(3, 3) = 3.0;
  SparseLdlt ldlt;
  ASSERT_TRUE(ldlt.factorize(K, 0.0));
  EXPECT_EQ(ldlt.inertia().negative, 1);
  EXPECT_EQ(ldlt.inertia().zero, 1);
  EXPECT_EQ(ldlt.inertia().positive, 2);
  EXPECT_LT(ldlt.shift(), 0.0);  // the kept factorization is regular
  Vector b = Vector::Ones(4);
  EXPECT_TRUE(ldlt.solve(b));
}

TEST(ContLowestEigenpairs, ShiftInvertLanczosMatchesDense) {
  const SparseMatrix K0 = test::random_symmetric(100, 3, 0.0, 11);
  const Eigen::SelfAdjointEigenSolver<Matrix> dense{Matrix(K0)};
  const int k = 6;
  // 0 negatives (one factorization), 3 (< k: found at shift 0), 12 and 40 (> k: lower shifts).
  for (double shift : shifts_for(dense.eigenvalues(), {0, 3, 12, 40})) {
    SparseMatrix K = K0;
    for (int i = 0; i < K.rows(); ++i) K.coeffRef(i, i) -= shift;
    SparseLdlt ldlt;
    ASSERT_TRUE(ldlt.factorize(K, 0.0));
    Eigenpairs pairs;
    ASSERT_TRUE(lowest_eigenpairs(K, k, ldlt, EigenOptions{}, pairs)) << "shift " << shift;
    const Vector reference = dense.eigenvalues().head(k).array() - shift;
    const double error = max_relative_error(pairs.values, reference);
    EXPECT_LT(error, 1e-10) << "shift " << shift;
    si::test::record_verification_absolute("continuation-library",
                                           "lowest 6 eigenvalues, Lanczos vs dense, " +
                                               std::to_string(ldlt.inertia().negative) +
                                               " negative: max relative error",
                                           0.0, error, 1e-10, "Eigen dense SelfAdjointEigenSolver");
    for (int j = 0; j < k; ++j) {
      const double overlap = std::abs(pairs.vectors.col(j).dot(dense.eigenvectors().col(j)));
      EXPECT_GT(overlap, 1.0 - 1e-9) << "mode " << j << ", shift " << shift;
    }
  }
}

TEST(ContConstraintNullSpace, OrthonormalAndAnnihilatedByA) {
  const int nodes = 60;
  const int dofs = 3;
  const SparseMatrix A = test::node_constraints({0, 5, 6, 17, 33, 59}, dofs, nodes * dofs, 3);
  const NullSpaceBasis basis = constraint_null_space(A);
  EXPECT_EQ(basis.rank, 6);
  ASSERT_EQ(basis.Z.cols(), nodes * dofs - 6);
  const Matrix Z(basis.Z);
  EXPECT_LT((Z.transpose() * Z - Matrix::Identity(Z.cols(), Z.cols())).norm(), 1e-13);
  EXPECT_LT((Matrix(A) * Z).norm(), 1e-13);
  // Local: a node's Householder block touches only that node's dofs.
  EXPECT_LE(basis.Z.nonZeros(), nodes * dofs - 6 * dofs + 6 * (dofs - 1) * dofs);
}

TEST(ContConstraintNullSpace, OverlappingAndRankDeficientRows) {
  // Rows 0 and 1 share dof 4 (one group); row 2 repeats row 3 (rank 1 in their group).
  SparseMatrix A(4, 12);
  A.insert(0, 3) = 1.0;
  A.insert(0, 4) = 2.0;
  A.insert(1, 4) = -1.0;
  A.insert(1, 5) = 0.5;
  A.insert(2, 8) = 1.0;
  A.insert(2, 9) = 1.0;
  A.insert(3, 8) = 2.0;
  A.insert(3, 9) = 2.0;
  const NullSpaceBasis basis = constraint_null_space(A);
  EXPECT_EQ(basis.rank, 3);
  const Matrix Z(basis.Z);
  ASSERT_EQ(Z.cols(), 9);
  EXPECT_LT((Z.transpose() * Z - Matrix::Identity(9, 9)).norm(), 1e-14);
  EXPECT_LT((Matrix(A) * Z).norm(), 1e-14);
}

// The restricted tangent: negative count exact and lowest eigenvalues to 1e-10 relative against
// the dense Z_d' K Z_d with Z_d from an SVD of A, for stable, slightly and strongly unstable K;
// with the default LDL' and with CHOLMOD's Cholesky first (LDL' when not positive definite).
void expect_restricted_tangent_matches_dense(const StabilityOptions& options,
                                             const std::string& name) {
  const int nodes = 70;
  const int dofs = 3;
  const int n = nodes * dofs;
  const SparseMatrix A = test::node_constraints({1, 9, 10, 30, 44, 45, 68}, dofs, n, 5);
  const Matrix Zd = test::dense_null_space(A);
  const SparseMatrix K0 = test::random_symmetric(nodes, dofs, 0.0, 13);
  const Vector reduced0 = test::dense_eigenvalues(Zd.transpose() * Matrix(K0) * Zd);
  const int modes = 4;
  for (double shift : shifts_for(reduced0, {0, 1, 2, 9})) {
    SparseMatrix K = K0;
    for (int i = 0; i < n; ++i) K.coeffRef(i, i) -= shift;
    Stability s;
    ASSERT_TRUE(analyse_stability(K, A, modes, s, options)) << "shift " << shift;
    const Vector reference = reduced0.head(modes).array() - shift;
    EXPECT_EQ(s.negative, count_below(reduced0, shift)) << "shift " << shift;
    EXPECT_EQ(s.zero, 0);
    const double error = max_relative_error(s.eigenvalues, reference);
    EXPECT_LT(error, 1e-10) << "shift " << shift;
    si::test::record_verification_absolute(
        "continuation-library",
        "restricted tangent Z'KZ, " + name + ", " + std::to_string(s.negative) +
            " negative: lowest 4 eigenvalues, max relative error",
        0.0, error, 1e-10, "dense Z_d' K Z_d, Z_d from an SVD of A");
    ASSERT_EQ(s.modes.size(), static_cast<std::size_t>(modes));
    const Matrix Kd(K);
    for (int j = 0; j < modes; ++j) {
      const Vector& v = s.modes[static_cast<std::size_t>(j)];
      EXPECT_NEAR(v.norm(), 1.0, 1e-12);
      EXPECT_LT((Matrix(A) * v).norm(), 1e-12);  // the mode keeps the constraints
      // Rayleigh quotient = eigenvalue; the residual K v - lambda v lies in range(A').
      EXPECT_NEAR(v.dot(Kd * v), s.eigenvalues(j), 1e-10 * std::abs(s.eigenvalues(j)));
      const Vector r = Kd * v - s.eigenvalues(j) * v;
      EXPECT_LT((Zd.transpose() * r).norm(), 1e-9 * Kd.norm());
    }
  }
}

TEST(ContStabilityAnalysis, RestrictedTangentMatchesDenseReducedSolve) {
  expect_restricted_tangent_matches_dense(StabilityOptions{}, "LDL'");
}

TEST(ContStabilityAnalysis, CholmodFirstMatchesDenseReducedSolve) {
  StabilityOptions options;
  options.factorization = cholmod_first_factorization();
  expect_restricted_tangent_matches_dense(options, "CHOLMOD LL' first");
  // The Cholesky is taken when positive definite, the LDL' otherwise.
  const SparseMatrix K = test::random_symmetric(30, 3, 0.0, 23);
  CholmodFirstFactorization f;
  ASSERT_TRUE(f.factorize(K, -1e3));
  EXPECT_TRUE(f.positive_definite());
  EXPECT_EQ(f.inertia().positive, 90);
  ASSERT_TRUE(f.factorize(
      K, 0.5 * (test::dense_eigenvalues(Matrix(K))(4) + test::dense_eigenvalues(Matrix(K))(5))));
  EXPECT_FALSE(f.positive_definite());
  EXPECT_EQ(f.inertia().negative, 5);
}

TEST(ContStabilityAnalysis, MultiplierDirectionCompletesTheNullVector) {
  // K v = -A' psi for a critical v: shift K so that the lowest reduced eigenvalue is zero.
  const int nodes = 20;
  const int dofs = 3;
  const int n = nodes * dofs;
  const SparseMatrix A = test::node_constraints({2, 7, 15}, dofs, n, 17);
  const SparseMatrix K0 = test::random_symmetric(nodes, dofs, 0.0, 19);
  Stability s0;
  ASSERT_TRUE(analyse_stability(K0, A, 1, s0));
  SparseMatrix K = K0;
  for (int i = 0; i < n; ++i) K.coeffRef(i, i) -= s0.eigenvalues(0);
  const Vector& v = s0.modes[0];  // also the critical mode of the shifted K
  const Vector psi = multiplier_direction(K, A, v);
  const Vector residual = K * v + SparseMatrix(A.transpose()) * psi;
  EXPECT_LT(residual.norm(), 1e-10 * Matrix(K).norm());
}

}  // namespace
}  // namespace si::cont
