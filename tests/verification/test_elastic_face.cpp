// The elastic face (`contact.local: anisotropic` with `local_support: shell`;
// indentation/elastic_face.hpp, docs/theory/local-indentation.md 6.10) in the indentation problem:
//  * the quarter plate reports the whole plate: the mirror images of a quarter model's forces
//    (and a node's own disc on the symmetry planes) reproduce the full model's influence
//    coefficients, a different sum over different nodes;
//  * energy: the linear fast path solves the QP min 1/2 lambda^T S lambda + (g0 - h)^T lambda,
//    S = C K^-1 C^T + C_face, whose optimal value's derivative in h is -F (the envelope theorem),
//    so W = int F dh = 1/2 lambda^T S lambda = U + E_local at every depth: the trapezoidal work
//    over a refined grid converges to the reported U + E_local at second order;
//  * the same balance on a nonlinear path (the Newton rows): d(U + E_local)/dh = F;
//  * KINSOL (the Newton rows with C's dense block) against the fast path, one model, by GMRES
//    and by the LU; a zone that follows the contact against every pair coupled;
//  * input errors: homogenised plies, naming the key and its line.
// Its agreement with a resolved 3-D model is measured against CalculiX (bench/calculix,
// docs/verification.md section 7), not here.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "../indentation/indentation_test_support.hpp"
#include "../verification_record.hpp"
#include "analysis/local_contact.hpp"
#include "continuation/kinsol_corrector.hpp"
#include "continuation/natural.hpp"
#include "core/error.hpp"
#include "indentation/linear_indentation.hpp"
#include "io/case_file.hpp"

namespace si {
namespace {

using testing::IndentationFixture;
using testing::isotropic_indentation_case;

const char* const kTable = "local-indentation";
const char* const kPlateShell = "{type: flat_circular_plate, radius: 25 mm, edge: clamped}";

IndentationFixture elastic_face_plate(
    const std::string& symmetry, double size_apex,
    JacobianSolverKind solver = JacobianSolverKind::kPreconditionedKrylov, double zone_bound = 0) {
  CaseFile c = isotropic_indentation_case(
      3.8, kPlateShell,
      "{size_apex: " + std::to_string(size_apex) +
          " mm, size_edge: 4 mm, refine_radius: 6 mm, symmetry: " + symmetry + "}",
      "linear", 12.7, "outer");
  c.contact.local = LocalContactModel::kAnisotropic;
  c.contact.local_support = LocalSupport::kShell;
  IndentationOptions o;
  o.linear_solver = solver;
  o.face_zone_bound = zone_bound;
  o.local = local_contact_law(c);
  EXPECT_EQ(o.local.kind, LocalLawKind::kElasticFace);
  return IndentationFixture(c, o);
}

TEST(ElasticFace, QuarterPlateReportsTheWholePlate) {
  const double depth = 0.1;
  IndentationFixture full = elastic_face_plate("full", 0.5);
  IndentationFixture quarter = elastic_face_plate("quarter", 0.5);
  LinearIndentation a(*full.problem), b(*quarter.problem);
  const IndentationState f = full.problem->evaluate(a.solve(depth), depth);
  const IndentationState q = quarter.problem->evaluate(b.solve(depth), depth);
  std::cout << "elastic face, plate at " << depth << " mm: force " << q.force << " / " << f.force
            << " N, face approach at the apex " << q.local_indentation << " / "
            << f.local_indentation << " mm, " << f.contact_nodes << " nodes in contact\n";
  const auto expect_same = [](double x, double y, const std::string& what) {
    test::record_verification(kTable, "elastic face, plate at 0.1 mm: quarter vs full, " + what, y,
                              x, 1e-8, "the full model (a different sum over different nodes)");
    EXPECT_NEAR(x, y, 1e-8 * std::abs(y)) << what;
  };
  expect_same(q.force, f.force, "force");
  expect_same(q.local_indentation, f.local_indentation, "face approach at the apex");
  expect_same(q.local_energy, f.local_energy, "face energy");
  expect_same(q.energy, f.energy, "strain energy");
  expect_same(q.apex_mid_deflection, f.apex_mid_deflection, "apex mid-plane deflection");
  EXPECT_GT(f.contact_nodes, 4);  // the contact spreads over rings: the coupling is exercised
  EXPECT_GT(f.local_indentation, 0);
}

// W(n) = trapezoidal int_0^H F dh on n equal steps; U + E_local at H. Error ratio 4 per halving.
TEST(ElasticFace, WorkEqualsStrainPlusFaceEnergy_SecondOrder) {
  const double depth = 0.1;
  IndentationFixture fx = elastic_face_plate("quarter", 0.5);
  LinearIndentation fast(*fx.problem);
  const IndentationState end = fx.problem->evaluate(fast.solve(depth), depth);
  const double stored = end.energy + end.local_energy;
  std::vector<double> errors;
  for (int n : {8, 16, 32}) {
    double work = 0, previous = 0;
    for (int i = 1; i <= n; ++i) {
      const double h = depth * i / n;
      const double force = fx.problem->evaluate(fast.solve(h), h).force;
      work += 0.5 * (previous + force) * depth / n;
      previous = force;
    }
    errors.push_back(work - stored);
    std::cout << "elastic face: " << n << " steps, W = " << work << ", U + E_local = " << stored
              << " N mm\n";
  }
  test::record_verification(kTable, "elastic face, plate to 0.1 mm: W (32 steps) vs U + E_local",
                            stored, stored + errors.back(), 1e-3,
                            "energy balance (the QP's envelope theorem)");
  EXPECT_NEAR(errors.back(), 0, 1e-3 * stored);
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double ratio = errors[k - 1] / errors[k];
    EXPECT_GT(ratio, 2.8) << k;
    EXPECT_LT(ratio, 5.7) << k;
  }
  EXPECT_GT(end.local_energy, 0);
}

// With nonlinear kinematics the face is still a linear spring network between the indenter and
// the shell, and the shell's contact forces are the gaps' gradients: the system is conservative,
// W = int F dh = U + E_local, that is d(U + E_local)/dh = F. Checked in that differential form
// (the trapezoidal work over a path converges only irregularly here: nodes keep entering the
// contact, each a kink in F(h)): central differences of U + E_local over +-1e-4 mm at 0.3, 0.5
// and 0.7 mm on the coarse quarter cap [0/90]2S (1 mm apex mesh), where the contact set is the
// same on both sides, against the force; the differences' own error is O(1e-8) relative.
TEST(ElasticFace, NonlinearPath_StoredEnergyRateIsTheForce) {
  CaseFile c = testing::coarse_cap_case("nonlinear", "[0/90]2S", "quarter", 1.0, 4.0);
  c.contact.local = LocalContactModel::kAnisotropic;
  c.contact.local_support = LocalSupport::kShell;
  IndentationOptions o;
  o.local = local_contact_law(c);
  IndentationFixture fx(c, o);
  IndentationProblem& p = *fx.problem;
  const double delta = 1e-4;
  cont::Vector z = p.initial_point();
  const auto state_at = [&](double h) {
    const cont::NewtonResult r = cont::solve_at(p, z, h, testing::tight_kinsol_settings(p));
    EXPECT_TRUE(r.converged) << r.reason;
    return p.evaluate(z, h);
  };
  for (double h : {0.3, 0.5, 0.7}) {
    const IndentationState below = state_at(h - delta);
    const IndentationState at = state_at(h);
    const IndentationState above = state_at(h + delta);
    ASSERT_EQ(below.contact_nodes, above.contact_nodes) << h;  // no kink in between
    const double rate =
        (above.energy + above.local_energy - below.energy - below.local_energy) / (2 * delta);
    std::cout << "elastic face, nonlinear cap at " << h << " mm: d(U + E_local)/dh = " << rate
              << " N, force " << at.force << " N, " << at.contact_nodes << " nodes, E_local "
              << at.local_energy << " N mm\n";
    test::record_verification(kTable,
                              "elastic face, nonlinear quarter cap at " +
                                  std::to_string(h).substr(0, 3) +
                                  " mm: d(U + E_local)/dh vs the force",
                              at.force, rate, 1e-6, "energy balance (a conservative system)");
    EXPECT_NEAR(rate, at.force, 1e-6 * at.force) << h;
    EXPECT_GT(at.local_energy, 0);
  }
}

// The same problem by KINSOL (the Newton rows with C's dense block) and by the fast path (C's
// columns in the Schur complement): two solvers of one model. KINSOL's linear solves by each
// route: GMRES with the coupled rows eliminated in the preconditioner (coupled_rows.hpp; it
// must never need the LU) and the LU of the whole Jacobian.
TEST(ElasticFace, KinsolMatchesTheFastPath) {
  const double depth = 0.1;
  for (const JacobianSolverKind solver :
       {JacobianSolverKind::kPreconditionedKrylov, JacobianSolverKind::kUmfpack}) {
    const bool krylov = solver == JacobianSolverKind::kPreconditionedKrylov;
    IndentationFixture fx = elastic_face_plate("quarter", 0.5, solver);
    IndentationProblem& p = *fx.problem;
    LinearIndentation fast(p);
    const IndentationState s = p.evaluate(fast.solve(depth), depth);
    cont::Vector z = p.initial_point();
    for (int i = 1; i <= 4; ++i) {
      const cont::NewtonResult r =
          cont::solve_at(p, z, depth * i / 4, testing::tight_kinsol_settings(p));
      ASSERT_TRUE(r.converged) << r.reason;
    }
    const IndentationState k = p.evaluate(z, depth);
    test::record_verification(kTable,
                              std::string("elastic face, plate at 0.1 mm: force, KINSOL (") +
                                  (krylov ? "GMRES" : "LU") + ") vs fast path",
                              s.force, k.force, 1e-8, "the fast path (another solver, same model)");
    EXPECT_NEAR(k.force, s.force, 1e-8 * s.force) << krylov;
    EXPECT_NEAR(k.local_indentation, s.local_indentation, 1e-8 * s.local_indentation) << krylov;
    EXPECT_EQ(k.contact_nodes, s.contact_nodes) << krylov;
    if (!krylov) continue;
    const ContactJacobianCounters work = p.solver_counters();
    std::cout << "elastic face, KINSOL with GMRES: " << work.krylov_solves << " solves, "
              << work.krylov_products << " products, " << work.cholesky << " factors\n";
    EXPECT_GT(work.krylov_solves, 0);
    EXPECT_EQ(work.lu_fallbacks, 0);
    EXPECT_LE(work.krylov_products, 3 * work.krylov_solves);
  }
}

// The Newton paths couple the candidates within a zone that follows the contact (starting at a
// quarter of its bound, widened after accepted points whose pressed nodes near its edge): a
// natural path to 0.5 mm (contact radius 1.12 mm) with the zone bounded at 4 mm (it starts at
// 1 mm and must widen) ends on the fast path's solution, where every pair is coupled. Bounded at
// 1 mm the zone cannot hold the contact, and the force differs: the zone is not a formality.
TEST(ElasticFace, ZoneFollowsTheContact) {
  const double depth = 0.5;
  IndentationFixture all = elastic_face_plate("quarter", 0.5);
  LinearIndentation fast(*all.problem);
  const IndentationState reference = all.problem->evaluate(fast.solve(depth), depth);
  ASSERT_GT(reference.contact_radius, 1.0);  // past the starting zone
  const auto path_force = [&](double bound) {
    IndentationFixture fx =
        elastic_face_plate("quarter", 0.5, JacobianSolverKind::kPreconditionedKrylov, bound);
    IndentationProblem& p = *fx.problem;
    cont::Settings settings;
    settings.method = cont::Method::kNatural;
    settings.step_initial = settings.step_max = 0.1;
    settings.p_max = depth;
    settings.newton = testing::tight_kinsol_settings(p);
    settings.detect_limit_points = false;
    const cont::Branch b = cont::natural(p, p.initial_point(), 0.0, settings);
    EXPECT_EQ(b.status, cont::Status::kReachedBound) << b.reason;
    return p.evaluate(b.points.back().x, b.points.back().p);
  };
  const IndentationState followed = path_force(4.0);
  std::cout << "elastic face, plate at " << depth << " mm: force " << followed.force
            << " N (zone to 4 mm) / " << reference.force << " N (every pair), contact radius "
            << reference.contact_radius << " mm\n";
  test::record_verification(kTable,
                            "elastic face, plate at 0.5 mm: force, zone following the "
                            "contact vs every pair coupled",
                            reference.force, followed.force, 1e-8,
                            "the fast path (every pair coupled)");
  EXPECT_NEAR(followed.force, reference.force, 1e-8 * reference.force);
  EXPECT_EQ(followed.contact_nodes, reference.contact_nodes);
  const IndentationState held = path_force(1.0);
  EXPECT_GT(std::abs(held.force - reference.force), 1e-3 * reference.force) << held.force;
}

void expect_input_error(const std::string& yaml, const std::string& key, int line) {
  try {
    parse_case_file(yaml, "face.yaml");
    FAIL() << "expected an input error naming " << key;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().key, key) << e.what();
    EXPECT_EQ(e.where().line, line) << e.what();
  }
}

TEST(ElasticFace, HomogenisedPlies_AreAnInputErrorNamingTheKey) {
  const std::string head =
      "material: {type: isotropic, E: 70000 MPa, nu: 0.3}\n"
      "laminate: {layup: \"[0]\", ply_thickness: 3.8 mm}\n"
      "shell: {type: flat_circular_plate, radius: 25 mm, edge: clamped}\n"
      "indenter: {shape: sphere, radius: 12.7 mm}\n";
  expect_input_error(head +
                         "kinematics: linear\ncontact:\n  local: anisotropic\n"
                         "  local_support: shell\n  local_plies: homogenised\n",
                     "contact.local_plies", 9);
}

}  // namespace
}  // namespace si
