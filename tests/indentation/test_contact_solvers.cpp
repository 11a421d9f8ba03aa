// The contact solve at fixed depths: KINSOL on the Fischer-Burmeister-type system against the
// primal-dual active-set method (issue 4 acceptance: agreement to 1e-8 relative), and the KKT
// conditions and global equilibrium at every converged depth.
#include <gtest/gtest.h>

#include "continuation/kinsol_corrector.hpp"
#include "indentation/active_set_solver.hpp"
#include "indentation/linear_indentation.hpp"
#include "indentation_test_support.hpp"

namespace si {
namespace {

using testing::coarse_cap_case;
using testing::IndentationFixture;

struct Path {
  std::vector<cont::Vector> points;
  std::vector<IndentationState> states;
  int iterations = 0;  // Newton iterations in all
};

Path kinsol_path(IndentationProblem& p, const std::vector<double>& depths) {
  Path out;
  cont::Vector z = p.initial_point();
  for (double h : depths) {
    const cont::NewtonResult r = cont::solve_at(p, z, h, testing::tight_kinsol_settings(p));
    EXPECT_TRUE(r.converged) << "h = " << h << ": " << r.reason;
    out.points.push_back(z);
    out.states.push_back(p.evaluate(z, h));
    out.iterations += r.iterations;
  }
  return out;
}

Path active_set_path(IndentationProblem& p, const std::vector<double>& depths) {
  Path out;
  cont::Vector z = p.initial_point();
  for (double h : depths) {
    const ActiveSetResult r = solve_active_set(p, z, h, 1e-12 * p.stiffness_scale());
    EXPECT_TRUE(r.converged) << "h = " << h << ": " << r.reason;
    out.points.push_back(z);
    out.states.push_back(p.evaluate(z, h));
  }
  return out;
}

void expect_kkt_and_equilibrium(const IndentationState& s, double force_scale, double kappa) {
  // Issue 4: KKT violations below 1e-8 of the force scale (gaps through kappa, N/mm).
  EXPECT_GT(s.min_multiplier, -1e-8 * force_scale);
  EXPECT_GT(kappa * s.min_gap, -1e-8 * force_scale);
  EXPECT_LT(kappa * s.max_complementarity, 1e-8 * force_scale * force_scale);
  // Sum of multipliers = support reactions along the direction of travel, to 1e-9.
  EXPECT_NEAR(s.force, s.reaction, 1e-9 * force_scale);
}

void expect_solvers_agree(const std::string& kinematics) {
  const std::vector<double> depths{0.25, 0.5, 0.75, 1.0, 1.5};
  IndentationFixture fb(coarse_cap_case(kinematics, "[0/0]2S"));
  IndentationOptions min_options;
  min_options.ncp = NcpFunction::kMin;
  IndentationFixture pdas(coarse_cap_case(kinematics, "[0/0]2S"), min_options);
  const Path a = kinsol_path(*fb.problem, depths);
  const Path b = active_set_path(*pdas.problem, depths);
  for (std::size_t k = 0; k < depths.size(); ++k) {
    const double F = a.states[k].force;
    EXPECT_GT(F, 0);
    EXPECT_NEAR(a.states[k].force, b.states[k].force, 1e-8 * F) << depths[k];
    const int nf = fb.problem->num_shell_unknowns();
    const double u = a.points[k].head(nf).cwiseAbs().maxCoeff();
    EXPECT_LT((a.points[k].head(nf) - b.points[k].head(nf)).cwiseAbs().maxCoeff(), 1e-8 * u);
    expect_kkt_and_equilibrium(a.states[k], F, fb.problem->stiffness_scale());
    expect_kkt_and_equilibrium(b.states[k], F, fb.problem->stiffness_scale());
  }
}

TEST(ContactSolvers, KinsolAndActiveSetAgreeOnTheCap_Nonlinear) {
  expect_solvers_agree("nonlinear");
}

TEST(ContactSolvers, KinsolAndActiveSetAgreeOnTheCap_Linear) {
  expect_solvers_agree("linear");
}

// The KINSOL runs' complementarity function (Fischer-Burmeister where lambda, kappa g >= 0, min
// elsewhere: ncp_function.hpp) has Fischer-Burmeister's solutions, and from each depth's
// starting point (the previous solution, so that new contact nodes start infeasible) KINSOL
// needs fewer iterations with it (measured: 26 against 33 over the five depths).
TEST(ContactSolvers, FischerBurmeisterMinHasTheSolutionsOfFischerBurmeisterInFewerIterations) {
  const std::vector<double> depths{0.25, 0.5, 0.75, 1.0, 1.5};
  IndentationOptions fb_options;
  fb_options.ncp = NcpFunction::kFischerBurmeister;
  IndentationFixture fb(coarse_cap_case("nonlinear", "[0/0]2S"), fb_options);
  IndentationFixture hybrid(coarse_cap_case("nonlinear", "[0/0]2S"));
  const Path a = kinsol_path(*fb.problem, depths);
  const Path b = kinsol_path(*hybrid.problem, depths);
  const int nf = fb.problem->num_shell_unknowns();
  for (std::size_t k = 0; k < depths.size(); ++k) {
    const double F = a.states[k].force;
    EXPECT_NEAR(a.states[k].force, b.states[k].force, 1e-9 * F) << depths[k];
    const double u = a.points[k].head(nf).cwiseAbs().maxCoeff();
    EXPECT_LT((a.points[k].head(nf) - b.points[k].head(nf)).cwiseAbs().maxCoeff(), 1e-9 * u);
  }
  EXPECT_LT(b.iterations, a.iterations);
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// Issue 4: with linear kinematics the fast path (K factored once, the LCP on the candidates)
// and the full KINSOL solve of the same system agree to 1e-10.
TEST(ContactSolvers, LinearFastPathAgreesWithKinsol) {
  IndentationFixture f(coarse_cap_case("linear", "[45/-45]2S"));
  IndentationProblem& p = *f.problem;
  LinearIndentation fast(p);
  cont::Vector z = p.initial_point();
  for (double h : {0.2, 0.6, 1.0, 2.0, 1.3}) {  // also back down: the warm start must unload
    const cont::NewtonResult r = cont::solve_at(p, z, h, testing::tight_kinsol_settings(p));
    ASSERT_TRUE(r.converged) << r.reason;
    const cont::Vector zf = fast.solve(h);
    const int nf = p.num_shell_unknowns();
    const auto rel = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
      return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
    };
    EXPECT_LT(rel(zf.head(nf), z.head(nf)), 1e-10) << h;                        // displacements
    EXPECT_LT(rel(zf.tail(z.size() - nf), z.tail(z.size() - nf)), 1e-10) << h;  // multipliers
    const IndentationState s = p.evaluate(zf, h);
    expect_kkt_and_equilibrium(s, s.force, p.stiffness_scale());
    // The force alone (the onset watch's): the same bits as the whole state's.
    const Eigen::Index nc = zf.size() - nf;
    EXPECT_EQ(p.indenter_force(zf), s.force) << h;
    EXPECT_EQ(p.indenter_force_of(zf.tail(nc)), s.force) << h;
    // lambda without the back-substitution: the same QP solved again (warm).
    EXPECT_LT(rel(fast.multipliers(h), zf.tail(nc)), 1e-12) << h;
    EXPECT_EQ(p.indenter_force(z), p.evaluate(z, h).force) << h;  // and of the KINSOL solve
  }
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// The default Jacobian solver (Cholesky-preconditioned GMRES, contact_jacobian_solver.hpp) and a
// direct LU of the Jacobian give the same KINSOL path on the nonlinear cap, where the chart
// transform makes the Jacobian unsymmetric and the contact set grows between depths.
TEST(ContactSolvers, PreconditionedKrylovAgreesWithDirectLu_Nonlinear) {
  const std::vector<double> depths{0.5, 1.0, 2.0};
  IndentationOptions lu_options;
  lu_options.linear_solver = JacobianSolverKind::kUmfpack;
  IndentationFixture krylov(coarse_cap_case("nonlinear", "[45/-45]2S"));
  IndentationFixture lu(coarse_cap_case("nonlinear", "[45/-45]2S"), lu_options);
  const Path a = kinsol_path(*krylov.problem, depths);
  const Path b = kinsol_path(*lu.problem, depths);
  const int nf = lu.problem->num_shell_unknowns();
  for (std::size_t k = 0; k < depths.size(); ++k) {
    // Both stop at the tight tolerance (1e-12 of the stiffness scale): agreement to 1e-9.
    EXPECT_NEAR(a.states[k].force, b.states[k].force, 1e-9 * b.states[k].force) << depths[k];
    const double u = b.points[k].head(nf).cwiseAbs().maxCoeff();
    EXPECT_LT((a.points[k].head(nf) - b.points[k].head(nf)).cwiseAbs().maxCoeff(), 1e-9 * u);
  }
  EXPECT_GT(krylov.problem->solver_counters().krylov_solves, 0);
  EXPECT_EQ(lu.problem->solver_counters().krylov_solves, 0);
}

}  // namespace
}  // namespace si
