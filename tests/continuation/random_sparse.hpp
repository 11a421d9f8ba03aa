// Reproducible sparse symmetric matrices with a structural pattern (nodes of a few dofs coupled to
// neighbouring nodes) and sparse constraint rows, for the stability tools' tests.
#pragma once

#include <random>
#include <vector>

#include <Eigen/Eigenvalues>

#include "continuation/sparse_matrix.hpp"

namespace si::cont::test {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

// K = B + B' + n I on `nodes` nodes of `dofs` dofs: node i couples to i+1, i+2 and a random node,
// with full dense blocks, then shifted by -shift I (both triangles stored).
inline SparseMatrix random_symmetric(int nodes, int dofs, double shift, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, nodes - 1);
  Triplets t;
  auto block = [&](int a, int b) {
    for (int i = 0; i < dofs; ++i)
      for (int j = 0; j < dofs; ++j) {
        const double v = u(rng);
        t.emplace_back(a * dofs + i, b * dofs + j, v);
        t.emplace_back(b * dofs + j, a * dofs + i, v);
      }
  };
  for (int a = 0; a < nodes; ++a) {
    block(a, a);
    if (a + 1 < nodes) block(a, a + 1);
    if (a + 2 < nodes) block(a, a + 2);
    const int r = pick(rng);
    if (r != a) block(a, r);
  }
  const int n = nodes * dofs;
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, 6.0 * dofs - shift);
  SparseMatrix K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

// One constraint row per listed node, touching that node's dofs with random coefficients.
inline SparseMatrix node_constraints(const std::vector<int>& nodes, int dofs, int n,
                                     unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Triplets t;
  for (std::size_t r = 0; r < nodes.size(); ++r)
    for (int i = 0; i < dofs; ++i) t.emplace_back(static_cast<int>(r), nodes[r] * dofs + i, u(rng));
  SparseMatrix A(static_cast<int>(nodes.size()), n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// An orthonormal basis of null(A) from a dense SVD (independent of the Householder construction).
inline Matrix dense_null_space(const SparseMatrix& A) {
  const Matrix a(A);
  Eigen::JacobiSVD<Matrix> svd(a, Eigen::ComputeFullV);
  const auto& s = svd.singularValues();
  const double tol = 1e-12 * (s.size() ? s(0) : 1.0);
  const Eigen::Index rank = (s.array() > tol).count();
  return svd.matrixV().rightCols(a.cols() - rank);
}

inline Vector dense_eigenvalues(const Matrix& M) {
  return Eigen::SelfAdjointEigenSolver<Matrix>(M, Eigen::EigenvaluesOnly).eigenvalues();
}

}  // namespace si::cont::test
