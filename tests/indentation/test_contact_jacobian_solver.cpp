// The preconditioned Krylov solver of the indentation Jacobian against a dense LU of the same
// matrix (a different method), on a small synthetic Jacobian with the structure of
// contact_jacobian_solver.hpp: a chart-transformed SPD shell block, an exactly active, a partly
// active and an inactive complementarity row, a node with both rotation components free and one
// with one prescribed.
#include "indentation/contact_jacobian_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <Eigen/Dense>

#include "core/error.hpp"

namespace si {
namespace {

constexpr int kShell = 12;  // node 0: eqs 0-4 (rotations 3, 4); node 1: 5-8 (rotation 8); 9-11
constexpr double kKappa = 50.0;

struct Synthetic {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(kShell, kShell);  // symmetric
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(kShell, kShell);  // drilling-like, unsymmetric
  std::vector<ShellChart::RotationBlock> rotations;
  std::vector<ContactJacobianRow> rows;
  // The rows' compliance C (rows x rows, mm/N, symmetric), or empty: row i of the contact block
  // reads b_i C_ij in column j != i, kept beside J (row_coupling.hpp).
  Eigen::MatrixXd compliance;

  Eigen::MatrixXd full_T() const {
    Eigen::MatrixXd T = Eigen::MatrixXd::Identity(kShell, kShell);
    for (const ShellChart::RotationBlock& r : rotations) {
      if (r.eq_a >= 0) T(r.eq_a, r.eq_a) = r.T(0, 0);
      if (r.eq_b >= 0) T(r.eq_b, r.eq_b) = r.T(1, 1);
      if (r.eq_a >= 0 && r.eq_b >= 0) {
        T(r.eq_a, r.eq_b) = r.T(0, 1);
        T(r.eq_b, r.eq_a) = r.T(1, 0);
      }
    }
    return T;
  }

  // J = [K T + D, -G; b G^T T, diag(a)] (indentation_problem.hpp).
  SparseMatrix jacobian() const {
    const int n = kShell + static_cast<int>(rows.size());
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n, n);
    const Eigen::MatrixXd T = full_T();
    J.topLeftCorner(kShell, kShell) = K * T + D;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const int m = kShell + static_cast<int>(i);
      Eigen::VectorXd G = Eigen::VectorXd::Zero(kShell);
      for (int k = 0; k < 5; ++k)
        if (rows[i].eq[k] >= 0) G[rows[i].eq[k]] = rows[i].gradient[k];
      J.block(0, m, kShell, 1) = -G;
      J.block(m, 0, 1, kShell) = rows[i].b * (T.transpose() * G).transpose();
      J(m, m) = rows[i].a;
    }
    return J.sparseView();
  }

  RowCoupling coupling() const {
    RowCoupling c;
    if (compliance.size() == 0) return c;
    const int n = static_cast<int>(rows.size());
    auto C = std::make_shared<Eigen::MatrixXd>(compliance.transpose());
    C->diagonal().setZero();
    c.coefficients = C;
    c.scale.resize(n);
    for (int i = 0; i < n; ++i) {
      c.members.push_back(i);
      c.scale[i] = rows[i].b;
    }
    return c;
  }

  // The matrix solved: J with the couplings, assembled densely (a different route from
  // RowCoupling's).
  SparseMatrix full() const {
    Eigen::MatrixXd J = Eigen::MatrixXd(jacobian());
    for (Eigen::Index i = 0; i < compliance.rows(); ++i)
      for (Eigen::Index j = 0; j < compliance.cols(); ++j)
        if (j != i) J(kShell + i, kShell + j) += rows[i].b * compliance(i, j);
    return J.sparseView();
  }
};

Synthetic make_synthetic(double shell_sign = 1.0) {
  Synthetic s;
  std::srand(11);
  const Eigen::MatrixXd R = Eigen::MatrixXd::Random(kShell, kShell);
  s.K = shell_sign * (R * R.transpose() + kShell * Eigen::MatrixXd::Identity(kShell, kShell));
  ShellChart::RotationBlock both;
  both.eq_a = 3;
  both.eq_b = 4;
  both.T << 0.98, 0.07, -0.05, 1.01;
  ShellChart::RotationBlock one;
  one.eq_a = 8;
  one.T << 0.97, 0.0, 0.0, 1.0;
  s.rotations = {both, one};
  const auto row = [](std::array<int, 5> eq, double a, double b) {
    ContactJacobianRow r;
    r.eq = eq;
    for (int k = 0; k < 5; ++k) r.gradient[k] = 0.3 * k - 0.5 + 0.1 * eq[0];
    r.a = a;
    r.b = b;
    return r;
  };
  s.rows = {row({0, 1, 2, 3, 4}, 0.0, 1.2 * kKappa),   // fully active: phi_a = 0
            row({5, 6, 7, 8, -1}, 0.4, 0.7 * kKappa),  // partly active
            row({0, 1, 2, 3, 4}, 1.0, 0.0)};           // inactive
  return s;
}

// The elastic face's rows read each other's multipliers (coupled_rows.hpp): row i of the
// contact block is d_a,i e_i + b_i C_i with C a symmetric positive compliance (mm/N), its
// diagonal a_i = d_a,i + b_i C_ii. Rows 0 (active) and 1 (partly active) and a fourth, active row
// on the free eqs 9-11 couple; the inactive row 2 (b = 0) reads nothing but is read by them.
Synthetic make_coupled(double shell_sign = 1.0) {
  Synthetic s = make_synthetic(shell_sign);
  ContactJacobianRow free_node;
  free_node.eq = {9, 10, 11, -1, -1};
  free_node.gradient = {0.6, -0.4, 1.0, 0.0, 0.0};
  free_node.a = 0.0;
  free_node.b = 0.9 * kKappa;
  s.rows.push_back(free_node);
  Eigen::Matrix4d C;
  C << 1.0, 0.4, 0.2, 0.3, 0.4, 1.1, 0.25, 0.2, 0.2, 0.25, 0.9, 0.1, 0.3, 0.2, 0.1, 1.2;
  C /= kKappa;
  s.compliance = C;
  for (int i = 0; i < 4; ++i) s.rows[i].a += s.rows[i].b * C(i, i);
  return s;
}

// n active rows on the free eqs 9-11, coupled by C_ij = exp(-|i - j|) / kappa (positive
// definite): a patch of pressed nodes larger or smaller than the correction's bound.
Synthetic make_many_coupled(int n) {
  Synthetic s = make_synthetic();
  s.rows.clear();
  for (int i = 0; i < n; ++i) {
    ContactJacobianRow r;
    r.eq = {9, 10, 11, -1, -1};
    r.gradient = {0.6 + 0.001 * i, -0.4, 1.0 - 0.002 * i, 0.0, 0.0};
    r.b = 0.9 * kKappa;
    r.a = r.b / kKappa;  // d_a = 0 plus b C_ii
    s.rows.push_back(r);
  }
  s.compliance = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) s.compliance(i, j) = std::exp(-std::abs(i - j)) / kKappa;
  return s;
}

void expect_matches_dense_lu(ContactJacobianSolver& solver, const SparseMatrix& J) {
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(J.rows(), -2.0, 1.0);
  const Eigen::VectorXd reference = Eigen::MatrixXd(J).partialPivLu().solve(b);
  const Eigen::VectorXd x = solver.solve(b);
  EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm());
}

// J (with its couplings) factored by `solver` and solved to the dense LU's answer (the solver
// keeps a pointer to J: J lives until the solve is done).
void factor_and_check(ContactJacobianSolver& solver, const Synthetic& s) {
  const SparseMatrix J = s.jacobian();
  solver.factorize(J, kShell, s.rotations, s.rows, 0, s.coupling());
  expect_matches_dense_lu(solver, s.full());
}

// The same by a fresh solver with UMFPACK as its fallback, which took `cholesky` Cholesky
// factors of H, `lu` LUs and `ldlt` LDL' factors of H, and at most `products` GMRES products.
void expect_fresh_solve(const Synthetic& s, long cholesky, long lu, long ldlt, long products) {
  ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
  factor_and_check(solver, s);
  const ContactJacobianCounters& c = solver.counters();
  EXPECT_EQ(c.cholesky, cholesky);
  EXPECT_EQ(c.lu_fallbacks, lu);
  EXPECT_EQ(c.ldlt, ldlt);
  EXPECT_LE(c.krylov_products, products);
}

// One factor, no LU, and the dense LU's solution in at most two GMRES products: the
// preconditioner is exact up to the condensation floor.
void expect_exact_preconditioner(const Synthetic& s) {
  expect_fresh_solve(s, 1, 0, 0, 2);
}

// T^T (K T) is symmetric: the preconditioner is exact up to the condensation floor.
TEST(ContactJacobianSolver, ExactStructureSolvesInTwoProducts) {
  expect_exact_preconditioner(make_synthetic());
}

// A border (the local approach alpha of a power-law local contact: its column d_b kappa u' in the
// contact rows, its row the symmetry factor on the multipliers, its corner -dF/dalpha) stays in
// J; the preconditioner eliminates it through the factor, so the solve is still J's own and
// takes as few products as without the border.
TEST(ContactJacobianSolver, BorderedByTheLocalApproach_SolvesTheBorderedMatrix) {
  const Synthetic s = make_synthetic();
  const Eigen::MatrixXd inner = Eigen::MatrixXd(s.jacobian());
  const int n = static_cast<int>(inner.rows());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(n + 1, n + 1);
  J.topLeftCorner(n, n) = inner;
  for (int i = kShell; i < n; ++i) {
    J(i, n) = s.rows[i - kShell].b * (0.3 + 0.2 * (i - kShell));  // b u'
    J(n, i) = 4.0;                                                // the symmetry factor
  }
  J(n, n) = -35.0;  // -dF/dalpha
  const SparseMatrix Js = J.sparseView();
  ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
  solver.factorize(Js, kShell, s.rotations, s.rows, 1);
  expect_matches_dense_lu(solver, Js);
  EXPECT_EQ(solver.counters().lu_fallbacks, 0);
  EXPECT_LE(solver.counters().krylov_products, 3);
}

// A drilling term and a stale factor (a new linearisation with the same pattern) cost GMRES
// products, not accuracy: the products are with the exact J.
TEST(ContactJacobianSolver, DrillingTermAndStaleFactorStayExact) {
  Synthetic s = make_synthetic();
  ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
  const SparseMatrix J1 = s.jacobian();
  solver.factorize(J1, kShell, s.rotations, s.rows);
  expect_matches_dense_lu(solver, J1);
  s.D(3, 4) = 0.4;
  s.D(4, 3) = -0.2;
  s.K *= 1.05;
  s.rows[1].a = 0.1;
  const SparseMatrix J2 = s.jacobian();
  solver.factorize(J2, kShell, s.rotations, s.rows);
  expect_matches_dense_lu(solver, J2);
  EXPECT_EQ(solver.counters().lu_fallbacks, 0);
}

// Candidates appended to the set (Problem::adapt) change J's pattern but not the shell block:
// the factor is kept, the new rows enter the preconditioner uncondensed, and the solve stays
// that of the exact J.
TEST(ContactJacobianSolver, AppendedRowsKeepTheFactorAndStayExact) {
  Synthetic s = make_synthetic();
  const ContactJacobianRow appended = s.rows.back();
  s.rows.pop_back();
  ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
  const SparseMatrix J1 = s.jacobian();
  solver.factorize(J1, kShell, s.rotations, s.rows);
  expect_matches_dense_lu(solver, J1);
  s.rows.push_back(appended);   // inactive
  s.rows.push_back(s.rows[1]);  // and a partly active one on node 1
  s.rows.back().a = 0.2;
  const SparseMatrix J2 = s.jacobian();
  ASSERT_NE(J2.rows(), J1.rows());
  solver.factorize(J2, kShell, s.rotations, s.rows);
  expect_matches_dense_lu(solver, J2);
  EXPECT_EQ(solver.counters().cholesky, 1);
  EXPECT_EQ(solver.counters().lu_fallbacks, 0);
}

// The Newton systems are solved to a relative residual (the inexact Newton forcing term of
// IndentationOptions::krylov_tolerance): the residual of the returned solution is within it,
// and a looser tolerance takes no more products than a tight one.
TEST(ContactJacobianSolver, SolvesToTheRequestedRelativeResidual) {
  Synthetic s = make_synthetic();
  s.D(3, 4) = 0.4;  // an unsymmetric part: GMRES needs several products
  s.D(4, 3) = -0.2;
  const SparseMatrix J = s.jacobian();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(J.rows(), -2.0, 1.0);
  long products[2] = {0, 0};
  const double tolerances[2] = {1e-4, 1e-12};
  for (int k = 0; k < 2; ++k) {
    ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack, tolerances[k]);
    solver.factorize(J, kShell, s.rotations, s.rows);
    const Eigen::VectorXd x = solver.solve(b);
    EXPECT_LE((J * x - b).norm(), tolerances[k] * b.norm()) << tolerances[k];
    products[k] = solver.counters().krylov_products;
  }
  EXPECT_LE(products[0], products[1]);
  EXPECT_THROW(ContactJacobianSolver(kKappa, LinearSolverKind::kUmfpack, 0.0), Error);
}

// Coupled rows are eliminated exactly by the preconditioner (a Woodbury correction to the
// factor over the coupled rows): GMRES takes as few products as without couplings (the
// diagonal alone leaves the preconditioned operator off the identity on the three coupled rows:
// 4 products). Coupled rows are no constraints to penalise: the stability route through the
// factor refuses them.
TEST(ContactJacobianSolver, CoupledRowsAreEliminatedExactly) {
  const Synthetic s = make_coupled();
  expect_exact_preconditioner(s);
  const SparseMatrix J = s.jacobian();
  ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
  solver.factorize(J, kShell, s.rotations, s.rows, 0, s.coupling());
  EXPECT_FALSE(solver.refresh_penalized({0, 3}));
}

// A stale factor of coupled rows (a new linearisation: other couplings, a row appended) costs
// products, not accuracy.
TEST(ContactJacobianSolver, CoupledRowsStayExactWithAStaleFactor) {
  Synthetic s = make_coupled();
  ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
  const SparseMatrix J1 = s.jacobian();
  solver.factorize(J1, kShell, s.rotations, s.rows, 0, s.coupling());
  expect_matches_dense_lu(solver, s.full());
  s.compliance *= 1.3;
  ContactJacobianRow appended = s.rows[1];
  appended.a = 0.5;
  appended.b = 0.0;  // reads nothing; row 0 reads it
  s.rows.push_back(appended);
  s.compliance.conservativeResize(5, 5);
  s.compliance.row(4).setZero();
  s.compliance.col(4).setZero();
  s.compliance(0, 4) = s.compliance(4, 0) = 0.2 / kKappa;
  const SparseMatrix J2 = s.jacobian();
  solver.factorize(J2, kShell, s.rotations, s.rows, 0, s.coupling());
  expect_matches_dense_lu(solver, s.full());
  EXPECT_EQ(solver.counters().lu_fallbacks, 0);
}

// Beyond 200 coupled rows the correction costs more solves than it saves (coupled_rows.cpp,
// kMaxCoupledRows): the rows condense on their diagonals and GMRES carries the couplings, to the
// same solution, without the LU; up to 200 the correction makes the preconditioner exact.
TEST(ContactJacobianSolver, ManyCoupledRowsAreLeftToGmres) {
  for (int n : {200, 201}) {
    const Synthetic s = make_many_coupled(n);
    const SparseMatrix J = s.jacobian();
    ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
    solver.factorize(J, kShell, s.rotations, s.rows, 0, s.coupling());
    expect_matches_dense_lu(solver, s.full());
    EXPECT_EQ(solver.counters().lu_fallbacks, 0) << n << " rows";
    if (n == 200)
      EXPECT_LE(solver.counters().krylov_products, 2);
    else
      EXPECT_GT(solver.counters().krylov_products, 4);
  }
}

// A fallback LU that always runs out of memory, as UMFPACK did on the 1e6-unknown cap.
class OutOfMemoryLu : public LinearSolver {
 public:
  LinearSolverKind kind() const override { return LinearSolverKind::kUmfpack; }
  std::string name() const override { return "out-of-memory LU"; }
  bool needs_spd() const override { return false; }
  void analyze(const SparseMatrix&) override {}
  void factorize(const SparseMatrix&) override { throw_numerical("out of memory (the test's LU)"); }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const override {
    ADD_FAILURE() << "solved with an LU that was never factored";
    return b;
  }
  double rcond() const override { return 0; }
  bool out_of_memory() const override { return true; }
};

// make_synthetic's shell block made slightly indefinite along the free eqs 9-11 (no contact row
// reads them, so the condensed rows cannot make H definite there): K projected off w, plus an
// eigenvalue of -1e-3 max|diag| along w. w is then an eigenvector of H too (T is the identity on
// eqs 9-11), the only negative one. (Much nearer 0, J's condition puts GMRES's 1e-12 out of
// double precision.)
Synthetic slightly_indefinite() {
  Synthetic s = make_synthetic();
  Eigen::VectorXd w = Eigen::VectorXd::Zero(kShell);
  w.tail(3).setOnes();
  w.normalize();
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(kShell, kShell) - w * w.transpose();
  const double mu = -1e-3 * s.K.diagonal().cwiseAbs().maxCoeff();
  s.K = P * s.K * P + mu * w * w.transpose();
  return s;
}

// Where H has no Cholesky factor the LU takes over, before H's LDL': near a singular J its
// solves are the more accurate. (No GMRES: the LU solves.)
TEST(ContactJacobianSolver, SlightlyIndefiniteShellBlockGoesToTheLuFirst) {
  expect_fresh_solve(slightly_indefinite(), 1, 1, 0, 0);
}

// Where the LU runs out of memory, the LDL' of H (indefinite, exact) preconditions GMRES on J
// itself, solved to the dense LU's answer in as few products as a Cholesky factor would take;
// from then on no LU is tried (it cost minutes per attempt at 1e6 unknowns), and a definite H
// goes back to its Cholesky.
TEST(ContactJacobianSolver, LuOutOfMemoryGivesWayToTheLdltOfH) {
  const Synthetic s = slightly_indefinite();
  ContactJacobianSolver solver(kKappa, [] { return std::make_unique<OutOfMemoryLu>(); });
  factor_and_check(solver, s);
  EXPECT_EQ(solver.counters().lu_fallbacks, 1);
  EXPECT_EQ(solver.counters().ldlt, 1);
  EXPECT_EQ(solver.counters().cholesky, 1);  // not tried again after the LU's failure
  EXPECT_LE(solver.counters().krylov_products, 2);
  solver.forget_preconditioner();
  factor_and_check(solver, s);
  EXPECT_EQ(solver.counters().lu_fallbacks, 1);  // not tried again
  EXPECT_EQ(solver.counters().ldlt, 2);
  solver.forget_preconditioner();
  factor_and_check(solver, make_synthetic());
  EXPECT_EQ(solver.counters().ldlt, 2);
  EXPECT_EQ(solver.counters().cholesky, 3);
}

// A singular shell block (K of rank one: H is that and the condensed rows' rank-2 sum) has no
// Cholesky factor and no LDL'; with the LU out of memory as well, the error names the
// Cholesky's failure, the LDL''s and the LU's.
TEST(ContactJacobianSolver, NoFactorOfHAndNoLuSaysAllThree) {
  Synthetic s = make_synthetic();
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(kShell, 1.0, 2.0);
  s.K = v * v.transpose();
  s.D.setZero();
  const SparseMatrix J = s.jacobian();
  ContactJacobianSolver solver(kKappa, [] { return std::make_unique<OutOfMemoryLu>(); });
  try {
    solver.factorize(J, kShell, s.rotations, s.rows);
    ADD_FAILURE() << "factored without a factor";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
    EXPECT_NE(what.find("CHOLMOD: not positive definite, at column "), std::string::npos) << what;
    EXPECT_NE(what.find("its LDL' neither"), std::string::npos) << what;
    EXPECT_NE(what.find("out of memory (the test's LU)"), std::string::npos) << what;
  }
  try {
    solver.factorize(J, kShell, s.rotations, s.rows);
    ADD_FAILURE() << "factored without a factor";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("out of memory before, not tried again"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(solver.counters().lu_fallbacks, 1);
}

// An indefinite shell block (past a limit point) has no Cholesky factor: the LU takes over.
TEST(ContactJacobianSolver, IndefiniteShellBlockFallsBackToLu) {
  expect_fresh_solve(make_synthetic(-1.0), 1, 1, 0, 0);
}

// A singular J (a shell stiffness of rank one, dense so that J keeps its pattern) fails both
// routes, and the error says so for each: why the preconditioner's Cholesky failed and why the
// LU did (the 1e6 path's stall printed only "the Jacobian routine failed").
TEST(ContactJacobianSolver, SingularJacobianNamesBothFailedFactorizations) {
  Synthetic s = make_synthetic(-1.0);
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(kShell, 1.0, 2.0);
  s.K = v * v.transpose();
  s.D.setZero();
  const SparseMatrix J = s.jacobian();
  ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
  try {
    solver.factorize(J, kShell, s.rotations, s.rows);
    ADD_FAILURE() << "a singular Jacobian was factored";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
    const std::size_t cholesky = what.find("the preconditioner's factor: ");
    const std::size_t lu =
        what.find("the LU of the contact Jacobian (" + std::to_string(J.rows()) + " unknowns): ");
    ASSERT_NE(cholesky, std::string::npos) << what;
    ASSERT_NE(lu, std::string::npos) << what;
    EXPECT_LT(cholesky, lu) << what;
    EXPECT_NE(what.find("CHOLMOD: not positive definite, at column "), std::string::npos) << what;
    EXPECT_NE(what.find("UMFPACK", lu), std::string::npos) << what;
  }
}

// The LU that takes over factors J with the coupled rows' block (RowCoupling::added_to): the
// solution is still that of the coupled matrix.
// Couplings over fewer rows (a zone that changed while J's pattern did not) get an LU analysed
// anew; the same rows again reuse it.
TEST(ContactJacobianSolver, IndefiniteShellBlockWithCoupledRowsFallsBackToTheirLu) {
  Synthetic s = make_coupled(-1.0);
  ContactJacobianSolver solver(kKappa, LinearSolverKind::kUmfpack);
  solver.factorize(s.jacobian(), kShell, s.rotations, s.rows, 0, s.coupling());
  expect_matches_dense_lu(solver, s.full());
  EXPECT_EQ(solver.counters().lu_fallbacks, 1);
  // Rows 0 and 1 alone couple: their 2 x 2 block, the rows' b.
  const Eigen::MatrixXd pair = s.compliance.topLeftCorner(2, 2);
  s.compliance.setZero();
  s.compliance.topLeftCorner(2, 2) = pair;
  RowCoupling two;
  two.members = {0, 1};
  two.scale = Eigen::Vector2d(s.rows[0].b, s.rows[1].b);
  auto C = std::make_shared<Eigen::MatrixXd>(pair.transpose());
  C->diagonal().setZero();
  two.coefficients = C;
  const SparseMatrix J = s.jacobian();
  for (int k = 0; k < 2; ++k) {
    solver.factorize(J, kShell, s.rotations, s.rows, 0, two);
    expect_matches_dense_lu(solver, s.full());
  }
  EXPECT_EQ(solver.counters().lu_fallbacks, 3);
}

}  // namespace
}  // namespace si
