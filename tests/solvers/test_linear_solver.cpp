#include "solvers/linear_solver.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "../model/spring_net_element.hpp"
#include "../model/test_meshes.hpp"
#include "core/error.hpp"
#include "model/assembler.hpp"
#include "model/supports.hpp"
#include "solvers/ldlt_solver.hpp"

namespace si {
namespace {

SparseMatrix plate_tangent(const std::vector<Support>& supports, int n = 10) {
  const Mesh m = testing::square_plate(n, n);
  const DofMap dofs = make_dof_map(m, supports);
  const testing::SpringNetElement el;
  const Assembler assembler(m, dofs, el, testing::unused_law(), Kinematics::kNonlinear);
  std::vector<NodeState> s = reference_state(m);
  for (int i = 0; i < m.num_nodes(); ++i) s[i].u.z() = 0.1 * m.nodes[i].x() * m.nodes[i].x();
  Assembly a = assembler.make_assembly();
  assembler.assemble(s, {}, a);
  return a.tangent;
}

TEST(LinearSolver, CholmodUmfpackKluAndLdltAgree) {
  const SparseMatrix K = plate_tangent({{SupportKind::kClamped, "left", -1, {}}});
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 2.0);
  Eigen::VectorXd x[4];
  int i = 0;
  for (const LinearSolverKind kind : {LinearSolverKind::kCholmod, LinearSolverKind::kUmfpack,
                                      LinearSolverKind::kKlu, LinearSolverKind::kLdlt}) {
    auto solver = make_linear_solver(kind);
    EXPECT_EQ(solver->kind(), kind);
    solver->analyze(K);
    solver->factorize(K);
    x[i] = solver->solve(b);
    EXPECT_LT((K * x[i] - b).norm(), 1e-12 * b.norm());
    EXPECT_GT(solver->rcond(), kSingularRcond);
    // Refactorizing with new values and the same pattern reuses the analysis.
    SparseMatrix K2 = 2.0 * K;
    solver->factorize(K2);
    EXPECT_LT((solver->solve(b) - 0.5 * x[i]).norm(), 1e-12 * x[i].norm());
    ++i;
  }
  EXPECT_LT((x[0] - x[1]).norm(), 1e-12 * x[0].norm()) << (x[0] - x[1]).norm() / x[0].norm();
  EXPECT_LT((x[0] - x[2]).norm(), 1e-12 * x[0].norm()) << (x[0] - x[2]).norm() / x[0].norm();
  EXPECT_LT((x[0] - x[3]).norm(), 1e-12 * x[0].norm()) << (x[0] - x[3]).norm() / x[0].norm();
}

// The LDL' factors what the Cholesky cannot: the clamped plate's tangent shifted between its
// third and fourth eigenvalues (dense eigensolver) has three negative ones. D's negative pivots
// count them (Sylvester's law of inertia) and the solve is exact.
TEST(LinearSolver, LdltFactorsAnIndefiniteMatrixAndCountsItsNegativeEigenvalues) {
  const SparseMatrix K = plate_tangent({{SupportKind::kClamped, "left", -1, {}}}, 6);
  const Eigen::VectorXd lambda =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(K)).eigenvalues();
  const double sigma = 0.5 * (lambda[2] + lambda[3]);
  SparseMatrix I(K.rows(), K.cols());
  I.setIdentity();
  SparseMatrix A = K - sigma * I;
  A.makeCompressed();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  EXPECT_THROW(make_linear_solver(LinearSolverKind::kCholmod)->factorize(A), Error);
  LdltSolver ldlt;
  ldlt.factorize(A);
  EXPECT_EQ(ldlt.negative_pivots(), 3);
  const Eigen::VectorXd x = ldlt.solve(b);
  const Eigen::VectorXd reference = Eigen::MatrixXd(A).partialPivLu().solve(b);
  EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm());
}

// No supports: three free translations. Both solvers must say so, not return garbage.
TEST(LinearSolver, SingularFreeBodyIsReportedClearly) {
  const SparseMatrix K = plate_tangent({}, 6);
  for (const LinearSolverKind kind : {LinearSolverKind::kCholmod, LinearSolverKind::kUmfpack,
                                      LinearSolverKind::kKlu, LinearSolverKind::kLdlt}) {
    auto solver = make_linear_solver(kind);
    solver->analyze(K);
    try {
      solver->factorize(K);
      ADD_FAILURE() << solver->name() << " factorized a singular matrix, rcond " << solver->rcond();
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
      EXPECT_NE(std::string(e.what()).find("stiffness matrix is singular"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("insufficiently supported (free rigid-body motion)"),
                std::string::npos);
    }
  }
}

// Why a factorization failed is said as it is: CHOLMOD names the column of a pivot that is not
// positive (in the matrix's own numbering, not its fill-reducing order), which points at the
// node; a free body still reads as one.
TEST(LinearSolver, CholmodNamesTheColumnThatIsNotPositiveDefinite) {
  const int n = 10, bad = 7;
  std::vector<Eigen::Triplet<double>> t;
  // An arrow: column 0 couples all others, so the fill-reducing order moves it last and the
  // failed pivot's position in that order is not its column.
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, i == bad ? -1.0 : 2.0 + i);
  for (int i = 1; i < n; ++i) {
    t.emplace_back(0, i, 0.01);
    t.emplace_back(i, 0, 0.01);
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  auto solver = make_linear_solver(LinearSolverKind::kCholmod);
  try {
    solver->factorize(A);
    ADD_FAILURE() << "an indefinite matrix was factored";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
    EXPECT_NE(std::string(e.what()).find("not positive definite, at column 7 of 10"),
              std::string::npos)
        << e.what();
  }
}

// Only CHOLMOD needs (and reads only the lower triangle of) a symmetric positive-definite matrix;
// the messages name each solver.
TEST(LinearSolver, KindsBuildTheirSolvers) {
  EXPECT_TRUE(make_linear_solver(LinearSolverKind::kCholmod)->needs_spd());
  EXPECT_FALSE(make_linear_solver(LinearSolverKind::kUmfpack)->needs_spd());
  EXPECT_FALSE(make_linear_solver(LinearSolverKind::kKlu)->needs_spd());
  EXPECT_FALSE(make_linear_solver(LinearSolverKind::kLdlt)->needs_spd());
  EXPECT_EQ(make_linear_solver(LinearSolverKind::kCholmod)->name(), "cholmod");
  EXPECT_EQ(make_linear_solver(LinearSolverKind::kUmfpack)->name(), "umfpack");
  EXPECT_EQ(make_linear_solver(LinearSolverKind::kKlu)->name(), "klu");
  EXPECT_EQ(make_linear_solver(LinearSolverKind::kLdlt)->name(), "ldlt");
}

}  // namespace
}  // namespace si
