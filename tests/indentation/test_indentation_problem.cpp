#include "indentation/indentation_problem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "analysis/indentation_run.hpp"
#include "contact/anisotropic_local_law.hpp"
#include "indentation/active_set_solver.hpp"
#include "indentation/linear_indentation.hpp"

#include "indentation_test_support.hpp"
#include "section/vam_section.hpp"

namespace si {
namespace {

using testing::coarse_cap_case;
using testing::IndentationFixture;

using testing::exact_solves;
using testing::expect_jacobian_matches_fd;
using testing::trial_point;

TEST(IndentationProblem, NonlinearJacobianMatchesFiniteDifferences) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S"), exact_solves());
  expect_jacobian_matches_fd(*f.problem, 0.3);
}

TEST(IndentationProblem, LinearJacobianMatchesFiniteDifferences) {
  IndentationFixture f(coarse_cap_case("linear", "[45/-45]2S"), exact_solves());
  expect_jacobian_matches_fd(*f.problem, 0.3);
}

// The paper's option: weighted gaps of the interpolated traction with the F-bar rows
// (interpolated_contact.hpp), whose rows span each candidate's elements.
TEST(IndentationProblem, InterpolatedTractionJacobianMatchesFiniteDifferences) {
  const CaseFile c = coarse_cap_case("linear", "[45/-45]2S");
  IndentationOptions o;
  o.interpolated_traction = true;
  o.interpolated.fbar = true;
  o.interpolated.fbar_top = analyze_vam(c.laminate).Fbar_top;
  IndentationFixture f(c, exact_solves(o));
  expect_jacobian_matches_fd(*f.problem, 0.3);
}

// The direct LU route of the same Jacobian (the Krylov solver is the default).
TEST(IndentationProblem, NonlinearJacobianMatchesFiniteDifferences_DirectLu) {
  IndentationOptions o;
  o.linear_solver = JacobianSolverKind::kUmfpack;
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S"), o);
  expect_jacobian_matches_fd(*f.problem, 0.3);
}

// dF/dh against a central difference of the residual in h, at depth 0.3 mm off the solution.
void expect_depth_derivative_matches_fd(IndentationProblem& p) {
  const cont::Vector z = trial_point(p, 3);
  cont::Vector dp, fp, fm;
  ASSERT_TRUE(p.residual_p(z, 0.3, dp));
  ASSERT_TRUE(p.residual(z, 0.3 + 1e-6, fp));
  ASSERT_TRUE(p.residual(z, 0.3 - 1e-6, fm));
  EXPECT_LT(((fp - fm) / 2e-6 - dp).cwiseAbs().maxCoeff(), 1e-6 * p.stiffness_scale());
}

TEST(IndentationProblem, DepthDerivativeMatchesFiniteDifferences) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S"));
  expect_depth_derivative_matches_fd(*f.problem);
}

TEST(IndentationProblem, StartsAtFirstTouchWithNoForce) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S"));
  cont::Vector F;
  ASSERT_TRUE(f.problem->residual(f.problem->initial_point(), 0.0, F));
  EXPECT_LT(F.cwiseAbs().maxCoeff(), 1e-9 * f.problem->stiffness_scale());
  EXPECT_GT(f.problem->candidates().size(), 1u);
}

// A failed step's report names where its residual is largest: a shell unknown by its node's
// reference position and component (dof_map.hpp's node-major numbering), a contact row by its
// candidate node; an index outside z names nothing.
TEST(IndentationProblem, UnknownNamesSayWhichNodeAndComponent) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S"));
  const IndentationProblem& p = *f.problem;
  const int eq = 7;
  const int dof = p.dofs().free_dofs()[eq];
  const Vector3d& x = p.model().mesh.nodes[dof / kShellNodeDofs];
  char at[64];
  std::snprintf(at, sizeof at, " at (%.4g, %.4g, %.4g) mm", x.x(), x.y(), x.z());
  const char* components[] = {"u1", "u2", "u3", "rotation about v1", "rotation about v2"};
  EXPECT_EQ(p.unknown_name(eq), "node " + std::to_string(dof / kShellNodeDofs) + at + ", " +
                                    components[dof % kShellNodeDofs]);
  const int row = p.layout().lambda_begin() + 1;
  EXPECT_EQ(p.unknown_name(row).rfind(
                "the contact row of node " + std::to_string(p.candidates()[1]) + " at (", 0),
            0u)
      << p.unknown_name(row);
  EXPECT_EQ(p.unknown_name(p.size()), "");
}

// The gradients of the active constraints (for the tangent restricted to them, issue 15): one
// row per candidate the signature calls active, and, with linear kinematics (gradients frozen at
// the reference state), those rows of the fast path's contact matrix C; the nodal gaps' and the
// weighted gaps' alike.
void expect_active_gradients_are_active_rows_of_c(const std::string& traction) {
  CaseFile c = coarse_cap_case("linear", "[0/90]2S");
  c.contact.traction =
      traction == "interpolated" ? ContactTraction::kInterpolated : ContactTraction::kNodal;
  IndentationSetup s(c, 1);
  const double h = 2.0;
  const cont::Vector z = LinearIndentation(*s.problem).solve(h);
  const std::vector<int> active = s.problem->signature(z, h);
  const SparseMatrix G = s.problem->active_constraint_gradients(z, h);
  const Eigen::MatrixXd C = Eigen::MatrixXd(s.problem->contact_matrix());
  int rows = 0;
  for (std::size_t i = 0; i < active.size(); ++i) {
    if (!active[i]) continue;
    ASSERT_LT(rows, G.rows());
    const Eigen::RowVectorXd g = Eigen::MatrixXd(G).row(rows++);
    EXPECT_LE((g - C.row(static_cast<Eigen::Index>(i))).norm(), 1e-14 * C.norm()) << i;
  }
  EXPECT_EQ(rows, G.rows());
  EXPECT_GT(rows, 1);                                // the depth presses several nodes
  EXPECT_LT(rows, static_cast<int>(active.size()));  // and leaves candidates open
}

TEST(IndentationProblem, ActiveConstraintGradientsAreTheActiveRowsOfC_NodalGaps) {
  expect_active_gradients_are_active_rows_of_c("nodal");
}

TEST(IndentationProblem, ActiveConstraintGradientsAreTheActiveRowsOfC_WeightedGaps) {
  expect_active_gradients_are_active_rows_of_c("interpolated");
}

}  // namespace
}  // namespace si

namespace si {
namespace {

// Local contact in series (issue 7): a Hertz law with E* = 10 GPa (the paper ply's transverse
// modulus) for the 12.7 mm sphere, and the thin-layer law with c = 1e-4 mm/MPa (the order of
// c_L for a 3.8 mm carbon/epoxy laminate).
IndentationOptions with_local(const LocalContactLaw& law,
                              NcpFunction f = NcpFunction::kFischerBurmeister) {
  IndentationOptions o;
  o.local = law;
  o.ncp = f;
  return o;
}
const LocalContactLaw kHertz = hertz_law(12.7, 10000.0);
const LocalContactLaw kThinLayer{LocalLawKind::kThinLayer, 0.0, 1e-4, 0.0, nullptr, nullptr};

TEST(IndentationProblem, HertzLocalLaw_NonlinearJacobianMatchesFiniteDifferences) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S", "quarter"),
                       exact_solves(with_local(kHertz)));
  ASSERT_EQ(f.problem->num_local_unknowns(), 1);
  expect_jacobian_matches_fd(*f.problem, 0.3);
  // alpha borders the Krylov solver's matrix (ContactTerm::borders): no LU of the whole Jacobian.
  EXPECT_GT(f.problem->solver_counters().krylov_solves, 0);
  EXPECT_EQ(f.problem->solver_counters().lu_fallbacks, 0);
}

TEST(IndentationProblem, HertzLocalLaw_LinearJacobianMatchesFiniteDifferences) {
  IndentationFixture f(coarse_cap_case("linear", "[45/-45]2S"), exact_solves(with_local(kHertz)));
  expect_jacobian_matches_fd(*f.problem, 0.3);
}

TEST(IndentationProblem, ThinLayerLocalLaw_JacobianMatchesFiniteDifferences) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S"),
                       exact_solves(with_local(kThinLayer)));
  ASSERT_EQ(f.problem->num_local_unknowns(), 0);
  expect_jacobian_matches_fd(*f.problem, 0.3);
}

// The arclength metric (inner()): the mean square of the shell coordinates, a power law's alpha
// counting as one more, plus the mean square of every multiplier over kappa (mm), whatever local
// law is present: each unit vector has its documented weight, and different unknowns do not mix.
TEST(IndentationProblem, ArclengthMetric_WeighsTheShellAlphaAndEveryMultiplier) {
  for (const IndentationOptions& o :
       {IndentationOptions{}, with_local(kHertz), with_local(kThinLayer)}) {
    IndentationFixture f(coarse_cap_case("linear", "[0/90]2S"), o);
    const IndentationProblem& p = *f.problem;
    const UnknownLayout u = p.layout();
    ASSERT_GT(u.multipliers, 1);
    const double kappa = p.stiffness_scale();
    const double shell_weight = 1.0 / (u.shell + u.local);
    const double multiplier_weight = 1.0 / (u.multipliers * kappa * kappa);
    std::vector<std::pair<int, double>> probes = {
        {0, shell_weight},
        {u.shell - 1, shell_weight},
        {u.lambda_begin(), multiplier_weight},
        {u.lambda_begin() + u.multipliers - 1, multiplier_weight}};
    if (u.local) probes.emplace_back(u.alpha_index(), shell_weight);
    const auto unit = [&](int i) {
      cont::Vector e = cont::Vector::Zero(p.size());
      e[i] = 1;
      return e;
    };
    for (const auto& [i, weight] : probes) {
      EXPECT_NEAR(p.inner(unit(i), unit(i)), weight, 1e-12 * weight) << "unknown " << i;
      for (const auto& probe : probes) {
        const int j = probe.first;
        if (j == i) continue;
        EXPECT_EQ(p.inner(unit(i), unit(j)), 0.0) << i << ", " << j;
      }
    }
  }
}

// The dent's rows (hertz_dent.hpp): d g_i / d alpha = du/dalpha, 1 inside the patch and
// (2/pi) asin(a/r) outside. At alpha = 0.5 mm the patch radius (R alpha)^0.5 = 2.52 mm spans
// the 2 mm apex ring of the coarse cap and the rows beyond it are outside; the same with
// alpha = -0.5 mm (the odd extension Newton iterates may reach), and without a dent radius (the
// uniform approach alpha of every face point, the fallback).
TEST(IndentationProblem, HertzDentRows_JacobianMatchesFiniteDifferencesInsideAndOutsideThePatch) {
  const CaseFile c = coarse_cap_case("linear", "[45/-45]2S");
  {
    IndentationFixture f(c, exact_solves(with_local(kHertz)));
    const double a = std::sqrt(kHertz.radius * 0.5);
    int inside = 0, outside = 0;
    for (int n : f.problem->candidates()) {
      const double r = f.model.mesh.nodes[n].head<2>().norm();
      inside += r < 0.9 * a;
      outside += r > 1.1 * a && r < 3 * a;
    }
    EXPECT_GE(inside, 5);
    EXPECT_GE(outside, 5);
    expect_jacobian_matches_fd(*f.problem, 0.3, 0.5);
    expect_jacobian_matches_fd(*f.problem, 0.3, -0.5);
  }
  LocalContactLaw uniform = kHertz;
  uniform.radius = 0;
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S", "quarter"),
                       exact_solves(with_local(uniform)));
  expect_jacobian_matches_fd(*f.problem, 0.3, 0.5);
}

// The finite-thickness anisotropic law (contact/layer_contact_law.hpp: the paper's [0/90]2S as a
// free plate, resolved plies): its tabulated F(alpha), stiffness and dent rows against finite
// differences, with the patch (radius ~2.3 mm at alpha = 0.5 mm) over the 2 mm ring and rows
// outside it. The dent's rate is the flat punch's profile, equal to du/dalpha of the tables to
// their accuracy (~1e-3 of the rate), inside the FD check's tolerance.
TEST(IndentationProblem, AnisotropicPlateLaw_JacobianMatchesFiniteDifferences) {
  const CaseFile c = coarse_cap_case("linear", "[0/90]2S");
  const LocalContactLaw law =
      anisotropic_local_law(c.laminate, {LocalSupport::kPlate, LocalPlies::kResolved, 10.98, 0.0});
  IndentationFixture f(c, exact_solves(with_local(law)));
  expect_jacobian_matches_fd(*f.problem, 0.3, 0.5);
  IndentationFixture g(coarse_cap_case("nonlinear", "[0/90]2S", "quarter"),
                       exact_solves(with_local(law)));
  expect_jacobian_matches_fd(*g.problem, 0.3);
}

// The elastic face (local_support: shell): its coupling of every row to every other
// multiplier (the dense block of C over the candidates) and its diagonal, against finite
// differences, nonlinear (quarter: mirror images) and linear (full); the block beside J's
// pattern (row_coupling.hpp) through GMRES's products and through the LU's assembled matrix.
TEST(IndentationProblem, ElasticFace_JacobianMatchesFiniteDifferences) {
  const CaseFile c = coarse_cap_case("nonlinear", "[0/90]2S", "quarter");
  const LocalContactLaw law =
      anisotropic_local_law(c.laminate, {LocalSupport::kShell, LocalPlies::kResolved, 10.98, 0.0});
  ASSERT_EQ(law.kind, LocalLawKind::kElasticFace);
  IndentationFixture f(c, exact_solves(with_local(law)));
  expect_jacobian_matches_fd(*f.problem, 0.3);
  IndentationOptions lu = with_local(law);
  lu.linear_solver = JacobianSolverKind::kUmfpack;
  IndentationFixture d(c, lu);
  expect_jacobian_matches_fd(*d.problem, 0.3);
  IndentationFixture g(coarse_cap_case("linear", "[0/90]2S"), exact_solves(with_local(law)));
  expect_jacobian_matches_fd(*g.problem, 0.3);
}

TEST(IndentationProblem, HertzLocalLaw_DepthDerivativeMatchesFiniteDifferences) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S"), with_local(kHertz));
  expect_depth_derivative_matches_fd(*f.problem);
}

// The start (z = 0, h = 0, F = alpha = 0, where dF/dalpha = 0) is a solution with a regular
// Jacobian (Fischer-Burmeister rows: the alpha column keeps d_b kappa in the apex row; with the
// min function the tie lambda = kappa g = 0 there takes the lambda branch, and the continuation
// never factorises at a tie with h > 0 since the apex gap is then negative). Plain Newton (the
// active-set solver: no line search) from there to 0.3 mm converges quadratically once the
// residual is small: with e_k = r_k / r_0, log e_{k+1} / log e_k >= 1.8 for every step from
// e_k < 1e-2 that stays above roundoff (e_{k+1} > 1e-11). Measured with the dent: r = 2478,
// 70318, 13533, 3088, 725, 32, 0.098, 5.6e-7 N; order 2.19 (the first step overshoots: the
// linearisation at alpha = 0 has only the apex inside the patch, local-indentation.md 3).
TEST(IndentationProblem, HertzLocalLaw_RegularStartAndQuadraticNewton) {
  {
    IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S", "quarter"), with_local(kHertz));
    cont::Vector z = f.problem->initial_point(), F;
    ASSERT_TRUE(f.problem->residual(z, 0.0, F));
    EXPECT_LT(F.cwiseAbs().maxCoeff(), 1e-12 * f.problem->stiffness_scale());
    EXPECT_TRUE(f.problem->factorize(z, 0.0));
  }
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S", "quarter"),
                       with_local(kHertz, NcpFunction::kMin));
  IndentationProblem& p = *f.problem;
  cont::Vector z = p.initial_point();
  const ActiveSetResult r = solve_active_set(p, z, 0.3, 1e-9 * p.stiffness_scale());
  ASSERT_TRUE(r.converged) << r.reason;
  const std::vector<double>& n = r.residual_norms;
  int checked = 0;
  for (std::size_t k = 0; k < n.size(); ++k)
    std::cout << "  Newton " << k << ": " << n[k] << " N\n";
  for (std::size_t k = 0; k + 1 < n.size(); ++k) {
    const double e = n[k] / n[0], next = n[k + 1] / n[0];
    if (e < 1e-2 && next > 1e-11) {
      EXPECT_GE(std::log(next) / std::log(e), 1.8) << k;
      ++checked;
    }
  }
  EXPECT_GE(checked, 1);
  const IndentationState s = p.evaluate(z, 0.3);
  EXPECT_GT(s.local_indentation, 0);
  EXPECT_NEAR(s.force, kHertz.force(s.local_indentation), 1e-9 * s.force);
}

// No node on the indenter's axis (the sphere moved 0.7 mm and 0.4 mm off the apex's line, full
// 2 mm cap mesh): the first-touch node is the dent profile's centre (its r is 0, inside the
// patch at alpha = 0), so the start is still a solution with a regular Jacobian, and KINSOL
// reaches 0.2 mm from it, where the force is the law's and no gap is negative.
TEST(IndentationProblem, HertzDent_IndenterOffTheNodes_RegularStartAndSolve) {
  const CaseFile c = coarse_cap_case("nonlinear", "[0/90]2S");
  const ShellModel model = build_shell_model(c);
  IndenterPose pose;
  const Vector3d apex = model.mesh.nodes[model.apex_node()];
  pose.position = apex + Vector3d(0.7, 0.4, c.indenter.radius + 5.0);
  const std::unique_ptr<Indenter> indenter = make_indenter(c.indenter, pose);
  IndentationOptions o = with_local(kHertz);
  o.contact_offset = contact_face_offset(c);
  o.threads = 1;
  IndentationProblem p(model, *indenter, pose.direction, o);
  cont::Vector z = p.initial_point(), F;
  ASSERT_TRUE(p.residual(z, 0.0, F));
  EXPECT_LT(F.cwiseAbs().maxCoeff(), 1e-12 * p.stiffness_scale());
  EXPECT_TRUE(p.factorize(z, 0.0));
  const cont::NewtonResult r = cont::solve_at(p, z, 0.2, testing::tight_kinsol_settings(p));
  ASSERT_TRUE(r.converged) << r.reason;
  const IndentationState s = p.evaluate(z, 0.2);
  EXPECT_GT(s.local_indentation, 0);
  EXPECT_NEAR(s.force, kHertz.force(s.local_indentation), 1e-9 * s.force);
  EXPECT_GE(s.min_gap, -1e-9);
}

// The first-touch gap at the start is zero only to roundoff: on this linear quarter cap with
// the case's default pose it came out +1.8e-15 mm, which put the apex row on the lambda side of
// the Fischer-Burmeister kink (d_b = 0) and left the power law's alpha column empty: the start
// could not be factored. A gap within the travel's roundoff now takes the touch's derivatives.
TEST(IndentationProblem, HertzLocalLaw_LinearCap_StartIsRegularDespiteRoundoffInTheFirstGap) {
  CaseFile c = coarse_cap_case("linear", "[0/0]2S", "quarter", 1.5);
  c.contact.local = LocalContactModel::kHertz;
  IndentationSetup setup(c, 1, JacobianSolverKind::kUmfpack);
  IndentationProblem& p = *setup.problem;
  cont::Vector z = p.initial_point(), F;
  ASSERT_TRUE(p.residual(z, 0.0, F));
  EXPECT_LT(F.cwiseAbs().maxCoeff(), 1e-12 * p.stiffness_scale());
  EXPECT_TRUE(p.factorize(z, 0.0));
}

}  // namespace
}  // namespace si
