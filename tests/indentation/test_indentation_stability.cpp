// The stability of indentation points (indentation_stability.cpp; docs/theory/continuation.md
// 12): the library's count and lowest eigenvalue of the restricted tangent against a dense
// eigen-solve of Z'HZ on the same model, Z from an SVD of the active rows (an independent basis),
// the Hessian's symmetry and constraint rows, and the mode mapped into z.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>

#include "continuation/cholmod_factorization.hpp"
#include "continuation/kinsol_corrector.hpp"
#include "continuation/stability_analysis.hpp"
#include "indentation_test_support.hpp"

namespace si {
namespace {

using testing::coarse_cap_case;
using testing::IndentationFixture;

// The converged point at depth h (mm), reached in `steps` equal KINSOL steps from the start.
cont::Vector converged(IndentationProblem& p, double h, int steps) {
  cont::Vector z = p.initial_point();
  for (int i = 1; i <= steps; ++i) {
    const cont::NewtonResult r =
        cont::solve_at(p, z, h * i / steps, testing::tight_kinsol_settings(p));
    EXPECT_TRUE(r.converged) << r.reason;
  }
  return z;
}

// The eigenvalues of Z'HZ, ascending, with Z an orthonormal basis of null(A) from a dense SVD.
Eigen::VectorXd dense_restricted_eigenvalues(const SparseMatrix& H, const SparseMatrix& A) {
  const Eigen::MatrixXd Hd(H);
  Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(H.rows(), H.cols());
  if (A.rows() > 0) {
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(A), Eigen::ComputeFullV);
    const Eigen::Index rank = svd.rank();
    Z = svd.matrixV().rightCols(H.cols() - rank);
  }
  const Eigen::MatrixXd R = Z.transpose() * Hd * Z;
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(0.5 * (R + R.transpose())).eigenvalues();
}

int count_below(const Eigen::VectorXd& values, double sigma) {
  return static_cast<int>((values.array() < sigma).count());
}

// At a converged point of `c` at depth h: H symmetric to the Newton tolerance before its
// symmetric part is taken, A's rows the active contacts; then the library on H - sigma I (Z'Z =
// I, so its restriction is Z'HZ - sigma I) with sigma between the dense eigenvalues, giving
// 0, 1, 3 and 7 negative: exact counts and the lowest eigenvalue to 1e-8 relative. The problem's
// own call then at sigma = 0, its mode checked against the constraints.
void expect_library_matches_dense(const CaseFile& c, double h, int steps) {
  IndentationFixture f(c);
  IndentationProblem& p = *f.problem;
  ASSERT_TRUE(p.provides_stability());
  const cont::Vector z = converged(p, h, steps);
  const IndentationProblem::StabilityMatrices m = p.stability_matrices(z, h);
  EXPECT_GT(m.A.rows(), 1);  // several nodes press
  EXPECT_EQ(m.A.rows(), static_cast<Eigen::Index>(m.multipliers.size()));
  const Eigen::VectorXd dense = dense_restricted_eigenvalues(m.H, m.A);
  ASSERT_GT(dense.size(), 12);
  EXPECT_GT(dense[0], 0.0) << "the cap is stable at " << h << " mm";

  // Shifts midway between eigenvalues: k below, the nearest eigenvalue well clear of sigma.
  SparseMatrix I(m.H.rows(), m.H.cols());
  I.setIdentity();
  for (int k : {0, 1, 3, 7}) {
    const double sigma = k == 0 ? 0.0 : 0.5 * (dense[k - 1] + dense[k]);
    cont::Stability s;
    cont::StabilityOptions o;
    o.factorization = cont::cholmod_first_factorization();
    // k + 1 modes: all the negative ones at the first shift (with fewer, the library steps its
    // shift down by the found ones' spread, at most 8 times: not enough for 7 here).
    ASSERT_TRUE(cont::analyse_stability(m.H - sigma * I, m.A, k + 1, s, o)) << k;
    EXPECT_EQ(s.negative, count_below(dense, sigma)) << k;
    EXPECT_EQ(s.negative, k);
    EXPECT_EQ(s.zero, 0) << k;
    EXPECT_NEAR(s.eigenvalues[0], dense[0] - sigma, 1e-8 * std::abs(dense[0] - sigma)) << k;
  }

  // The problem's own call: stable, the same lowest eigenvalue, the mode a unit shell vector in
  // null(A) with the active multipliers' part and nothing elsewhere.
  cont::Stability s;
  ASSERT_TRUE(p.stability(z, h, 2, s));
  EXPECT_EQ(s.negative, 0);
  EXPECT_NEAR(s.eigenvalues[0], dense[0], 1e-8 * dense[0]);
  EXPECT_NEAR(s.eigenvalues[1], dense[1], 1e-8 * dense[1]);
  ASSERT_EQ(s.modes.size(), 2u);
  const int nf = p.num_shell_unknowns();
  const cont::Vector& mode = s.modes[0];
  ASSERT_EQ(mode.size(), z.size());
  EXPECT_NEAR(mode.head(nf).norm(), 1.0, 1e-12);
  EXPECT_LT((m.A * mode.head(nf)).norm(), 1e-10 * m.A.norm());
  cont::Vector rest = mode.tail(z.size() - nf);
  for (int j : m.multipliers) rest[j - nf] = 0;
  EXPECT_EQ(rest.cwiseAbs().maxCoeff(), 0.0);
}

// The Hessian's asymmetry at a converged point is the Newton residual's (continuation.md 12).
TEST(IndentationStability, NonlinearHessianSymmetricAtConvergedPoint) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S", "quarter"));
  IndentationProblem& p = *f.problem;
  const double h = 1.5;
  const cont::Vector z = converged(p, h, 3);
  const IndentationProblem::StabilityMatrices m = p.stability_matrices(z, h);
  EXPECT_LT(m.asymmetry, 1e-8);
  // Off the solution the dropped terms are the residual's: clearly not symmetric.
  cont::Vector off = z;
  off.head(p.num_shell_unknowns()).array() += 0.01;
  EXPECT_GT(p.stability_matrices(off, h).asymmetry, 100 * m.asymmetry);
}

// After factorize() at the point (what the continuation does before it asks), the analysis reads
// the factored Jacobian instead of assembling it again: the same H and A as assembled afresh
// (after a factorization elsewhere), to the round-off of the gaps' Newton guesses.
TEST(IndentationStability, FactoredJacobianReused_SameMatricesAsAssembled) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S", "quarter"));
  IndentationProblem& p = *f.problem;
  const double h = 1.5;
  const cont::Vector z = converged(p, h, 3);
  cont::Vector off = z;
  off.head(p.num_shell_unknowns()).array() += 1e-3;
  ASSERT_TRUE(p.factorize(off, h));
  const IndentationProblem::StabilityMatrices assembled = p.stability_matrices(z, h);
  ASSERT_TRUE(p.factorize(z, h));
  const IndentationProblem::StabilityMatrices reused = p.stability_matrices(z, h);
  EXPECT_LT(SparseMatrix(reused.H - assembled.H).norm(), 1e-12 * assembled.H.norm());
  EXPECT_LT(SparseMatrix(reused.A - assembled.A).norm(), 1e-12 * assembled.A.norm());
  EXPECT_EQ(reused.multipliers, assembled.multipliers);
  // Not the same matrix as the Jacobian factored elsewhere: the check above can fail.
  ASSERT_TRUE(p.factorize(off, h));
  EXPECT_GT(SparseMatrix(p.stability_matrices(off, h).H - assembled.H).norm(),
            1e-6 * assembled.H.norm());
}

TEST(IndentationStability, RestrictedTangentMatchesDenseEigenSolve_NonlinearCap) {
  expect_library_matches_dense(coarse_cap_case("nonlinear", "[0/90]2S", "quarter"), 1.5, 3);
}

TEST(IndentationStability, RestrictedTangentMatchesDenseEigenSolve_LinearCap) {
  expect_library_matches_dense(coarse_cap_case("linear", "[0/90]2S", "quarter"), 2.0, 1);
}

TEST(IndentationStability, NotProvidedWithALocalContactLaw) {
  CaseFile c = coarse_cap_case("nonlinear", "[0/90]2S", "quarter");
  IndentationOptions o;
  o.local.kind = LocalLawKind::kThinLayer;
  o.local.compliance = 1e-4;
  IndentationFixture f(c, o);
  EXPECT_FALSE(f.problem->provides_stability());
}

}  // namespace
}  // namespace si
