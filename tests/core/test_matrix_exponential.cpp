// exp(A) by scaling and squaring (core/matrix_exponential.hpp) against independent references:
// the eigen-decomposition of a diagonalisable matrix, the closed form of a Jordan block, and the
// group property exp(A) exp(-A) = I for the non-normal transfer matrices it is used on.
#include <gtest/gtest.h>

#include <complex>

#include "core/matrix_exponential.hpp"

namespace si {
namespace {

using Complex = std::complex<double>;
using Matrix6c = Eigen::Matrix<Complex, 6, 6>;

TEST(MatrixExponential, DiagonalisableMatrix_MatchesTheEigenDecomposition) {
  // A = V diag(mu) V^-1 with complex eigenvalues of modulus up to ~6: exp(A) = V diag(e^mu) V^-1.
  Matrix6c V = Matrix6c::Random() + 3.0 * Matrix6c::Identity();
  Eigen::Matrix<Complex, 6, 1> mu;
  mu << Complex(0.3, 1.2), Complex(-2.0, 0.5), Complex(5.5, -1.0), Complex(-4.0, -3.0),
      Complex(0.0, 6.0), Complex(1.0, 0.0);
  const Matrix6c A = V * mu.asDiagonal() * V.inverse();
  const Matrix6c reference = V * mu.array().exp().matrix().asDiagonal() * V.inverse();
  const Matrix6c E = matrix_exponential(A);
  EXPECT_LT((E - reference).norm(), 1e-11 * reference.norm());
}

TEST(MatrixExponential, JordanBlock_ClosedForm) {
  // exp(m I + N) = e^m (I + N + N^2/2) for N nilpotent of order 3: a defective matrix, where an
  // eigen-decomposition fails (the isotropic state matrix of layer_compliance.hpp is one).
  Eigen::Matrix3cd N = Eigen::Matrix3cd::Zero();
  N(0, 1) = 2.0;
  N(1, 2) = -3.0;
  const Complex m(1.5, -0.7);
  const Eigen::Matrix3cd A = m * Eigen::Matrix3cd::Identity() + N;
  const Eigen::Matrix3cd reference = std::exp(m) * (Eigen::Matrix3cd::Identity() + N + N * N / 2.0);
  EXPECT_LT((matrix_exponential(A) - reference).norm(), 1e-13 * reference.norm());
}

TEST(MatrixExponential, GroupProperty_ExpOfMinusAIsTheInverse) {
  // Entries up to 4: exp(A) and exp(-A) grow by ~1e3 each; the product's roundoff scales with
  // the product of their norms.
  Matrix6c A = 4.0 * Matrix6c::Random();
  const Matrix6c E = matrix_exponential(A), E_inv = matrix_exponential(Matrix6c(-A));
  EXPECT_LT((E * E_inv - Matrix6c::Identity()).norm(), 1e-14 * E.norm() * E_inv.norm());
}

}  // namespace
}  // namespace si
