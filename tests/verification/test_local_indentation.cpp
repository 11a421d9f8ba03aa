// Verification of the local contact law in series with the shell (issue 7 acceptance criteria;
// docs/theory/local-indentation.md, docs/verification.md "Local indentation (issue 7)"):
//  1. the laws against published numbers: Hertz (point-loads.md 4.3, the MOOSE sphere-on-sphere
//     check case) and Yang & Sun (point-loads.md 4.4, its worked example);
//  2. thick-plate limit: the local part is Hertz's law, and a very thick clamped plate, whose
//     global compliance is negligible, follows Hertz's F(delta) to 1 % in its travel;
//  3. thin-shell limit: a very stiff transverse modulus gives the `none` result, the difference
//     vanishing as the local approach does, k^(-2/3);
//  4. the isotropic clamped plate (a = 25 mm, t = 3.8 mm, E = 70 GPa, nu = 0.3, sphere 12.7 mm) at
//     0.05 mm: force / apex deflection within 5 % of the Mindlin plate stiffness under the
//     Hertzian pressure patch, on 1 mm and 0.5 mm apex meshes (0.25 mm with
//     SHELLINDENT_LONG_TESTS=1); the travel is the apex deflection plus the local approach;
//  5. energy: indenter work = strain energy + local contact energy, to the trapezoidal rule's
//     second-order error, while the nodes in contact lie inside the Hertzian patch; with nodes in
//     contact outside it, work = strain energy + local energy - D (the defect D derived there);
//  6. input errors naming contact.local.
// Every asserted comparison is also recorded for docs/verification.md (verification_record.hpp,
// table local-indentation). Numbers quoted in comments were measured on 2026-11-24 (Release,
// 2 vCPU).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "../indentation/indentation_test_support.hpp"
#include "../verification_record.hpp"
#include "analysis/indentation_run.hpp"
#include "analysis/local_contact.hpp"
#include "contact/hertz_dent.hpp"
#include "contact/local_contact_law.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "nonlinear_benchmark_support.hpp"

namespace si {
namespace {

using testing::IndentationFixture;
using testing::isotropic_indentation_case;
using testing::kIsotropicE;
using testing::kIsotropicNu;
using testing::tight_kinsol_settings;

constexpr double kSphere = 12.7;  // mm, the sphere radius
const char* const kTable = "local-indentation";
const char* const kPlateShell = "{type: flat_circular_plate, radius: 25 mm, edge: clamped}";

std::string quarter_mesh(double size_apex, double size_edge) {
  return "{size_apex: " + std::to_string(size_apex) +
         " mm, size_edge: " + std::to_string(size_edge) +
         " mm, refine_radius: 10 mm, symmetry: quarter}";
}

// Hertz for the isotropic plate material against a rigid sphere: E* = E / (1 - nu^2).
double plate_hertz_modulus() {
  return kIsotropicE / (1 - kIsotropicNu * kIsotropicNu);
}

// Hertz's F(delta) = (4/3) E* R^0.5 delta^1.5 (point-loads.md 4.3), written out independently of
// LocalContactLaw.
double hertz_force(double modulus, double radius, double delta) {
  return 4.0 / 3.0 * modulus * std::sqrt(radius) * std::pow(delta, 1.5);
}

// The isotropic plate case with a local law, run by natural continuation on the depth grid
// step, 2 step, ..., depth (linear kinematics: the power law routes it past the fast path).
CaseFile plate_case(double t, const std::string& mesh, const std::string& local, double depth,
                    double step) {
  CaseFile c = isotropic_indentation_case(t, kPlateShell, mesh, "linear", kSphere, "outer");
  c.contact.local = local == "hertz"      ? LocalContactModel::kHertz
                    : local == "yang_sun" ? LocalContactModel::kYangSun
                    : local == "vam"      ? LocalContactModel::kVam
                                          : LocalContactModel::kNone;
  c.path.method = PathMethod::kNatural;
  c.path.depth_max = depth;
  c.path.step = step;
  c.path.step_min = step / 1000;
  c.path.step_max = step;
  return c;
}

PathResult run_case(const CaseFile& c) {
  IndentationSetup setup(c, 1);
  PathResult r = run_indentation_path(setup);
  EXPECT_TRUE(r.completed) << r.reason;
  return r;
}

// ---------------------------------------------------------------------------------------------
// 1. The laws. MOOSE "Hertz Contact: Sphere on sphere" (point-loads.md 4.3): R1 = R2 = 2 (R = 1),
// E = 1.40625e7, nu = 0.25 for both -> E* = 7.5e6, and F = 1e4 gives delta = 0.01 (printed
// digits: exact to roundoff). Yang & Sun (point-loads.md 4.4 worked example, 4 printed digits):
// steel ball R = 6.35 mm, E_i = 207 GPa, nu_i = 0.3, E_2 = 10 GPa -> k = 3.218e4 N/mm^1.5, and
// F = 32.2, 360, 1018 N at alpha = 0.01, 0.05, 0.1 mm (3 to 4 digits).
TEST(LocalIndentationLaw, HertzSphereOnSphere_MooseCheckCase_PointLoads43) {
  const double modulus = hertz_modulus(1.40625e7, 0.25, 1.40625e7, 0.25);
  EXPECT_NEAR(modulus, 7.5e6, 1e-12 * 7.5e6);
  const LocalContactLaw law = hertz_law(1.0, modulus);
  test::record_verification(
      kTable, "Hertz law, MOOSE sphere on sphere (E* = 7.5e6, R = 1): delta at F = 1e4", 0.01,
      law.approach(1e4), 1e-10, "point-loads.md 4.3 (printed digits)");
  EXPECT_NEAR(law.approach(1e4), 0.01, 1e-12);
  EXPECT_NEAR(law.force(0.01), 1e4, 1e-12 * 1e4);
  // Energy = integral of F: (2/5) k alpha^2.5, its derivative the force (central difference).
  EXPECT_NEAR((law.energy(0.01 + 1e-7) - law.energy(0.01 - 1e-7)) / 2e-7, 1e4, 1e-6 * 1e4);
  EXPECT_NEAR((law.force(0.01 + 1e-7) - law.force(0.01 - 1e-7)) / 2e-7, law.stiffness(0.01),
              1e-6 * law.stiffness(0.01));
}

TEST(LocalIndentationLaw, YangSunSteelBallOnGraphiteEpoxy_WorkedExample_PointLoads44) {
  const LocalContactLaw law = yang_sun_law(6.35, 207000.0, 0.3, 10000.0);
  const std::string source = "point-loads.md 4.4 worked example (printed digits)";
  test::record_verification_absolute(kTable, "Yang & Sun k, steel ball R = 6.35 mm on E_2 = 10 GPa",
                                     3.218e4, law.k, 5.0, source);
  test::record_verification_absolute(kTable, "Yang & Sun F at alpha = 0.05 mm (N)", 360.0,
                                     law.force(0.05), 0.5, source);
  EXPECT_NEAR(law.k, 3.218e4, 0.5e1);  // 4 printed digits
  EXPECT_NEAR(law.force(0.01), 32.2, 0.05);
  EXPECT_NEAR(law.force(0.05), 360.0, 0.5);
  EXPECT_NEAR(law.force(0.1), 1018.0, 0.5);
}

// The law of a case: the paper's cap (carbon/epoxy, E_3 = 10 GPa, nu_23 of the library), rigid
// 12.7 mm sphere. yang_sun: k = (4/3) 12.7^0.5 E_3 = 47 516 N/mm^1.5 (point-loads.md 4.4 with
// a rigid ball), dent radius 12.7 mm; hertz: E* = E_3 / (1 - nu_23^2), R = 1/(1/12.7 + 1/80.9)
// (sphere on the cap), also the dent's radius.
TEST(LocalIndentationLaw, OfThePaperCap_YangSunAndHertzConstants) {
  CaseFile c = testing::coarse_cap_case("nonlinear", "[0/90]2S");
  c.contact.local = LocalContactModel::kYangSun;
  const double k_yang_sun = 4.0 / 3.0 * std::sqrt(12.7) * 10000.0;
  test::record_verification(kTable,
                            "yang_sun k of the paper's cap (E_3 = 10 GPa, rigid 12.7 mm sphere)",
                            k_yang_sun, local_contact_law(c).k, 1e-9, "point-loads.md 4.4");
  EXPECT_NEAR(local_contact_law(c).k, k_yang_sun, 1e-9 * 47516.0);
  EXPECT_EQ(local_contact_law(c).radius, 12.7);  // the dent's radius: the indenter's
  c.contact.local = LocalContactModel::kHertz;
  const double nu23 = c.laminate.plies.back().material.constants().nu23;
  const double R = 1 / (1 / 12.7 + 1 / 80.9);
  const double k_hertz = 4.0 / 3.0 * std::sqrt(R) * 10000.0 / (1 - nu23 * nu23);
  test::record_verification(kTable, "hertz k of the paper's cap (sphere on the cap: R = 10.98 mm)",
                            k_hertz, local_contact_law(c).k, 1e-9, "point-loads.md 4.3");
  EXPECT_NEAR(local_contact_law(c).k, k_hertz, 1e-9 * 47516.0);
  EXPECT_NEAR(local_contact_law(c).radius, R, 1e-12 * R);  // the relative radius
  c.contact.local = LocalContactModel::kNone;
  EXPECT_EQ(local_contact_law(c).kind, LocalLawKind::kNone);
}

// The anisotropic law of an isotropic plate: its half-space is Hertz's (the same k and dent radius
// as `hertz`, to roundoff), and its finite-thickness forms start as Hertz's (a/h -> 0).
TEST(LocalIndentationLaw, AnisotropicOfAnIsotropicPlate_IsHertzAtSmallContactRadius) {
  CaseFile c = plate_case(3.8, quarter_mesh(2.0, 4.0), "hertz", 0.05, 0.05);
  const LocalContactLaw hertz = local_contact_law(c);
  c.contact.local = LocalContactModel::kAnisotropic;
  const LocalContactLaw half_space = local_contact_law(c);
  test::record_verification(kTable, "anisotropic (half_space) k of an isotropic plate vs hertz",
                            hertz.k, half_space.k, 1e-10, "Hertz (point-loads.md 4.3)");
  EXPECT_NEAR(half_space.k, hertz.k, 1e-10 * hertz.k);
  EXPECT_EQ(half_space.radius, hertz.radius);
  for (LocalSupport support :
       {LocalSupport::kBondedBase, LocalSupport::kFrictionlessBase, LocalSupport::kPlate}) {
    c.contact.local_support = support;
    const LocalContactLaw law = local_contact_law(c);
    ASSERT_NE(law.layer, nullptr);
    const double alpha = 1e-7;  // a = 1.1e-3 mm against h = 1.9 or 3.8 mm
    EXPECT_NEAR(law.force(alpha) / hertz.force(alpha), 1.0, 2e-3);
    // Stiffer than the half-space once the contact radius is a fair fraction of h.
    EXPECT_GT(law.force(0.1), 1.1 * hertz.force(0.1));
  }
}

// ---------------------------------------------------------------------------------------------
// 2. Thick-plate limit: clamped plate a = 25 mm, t = 50 mm (t/a = 2: the global compliance
// ~1e-6 mm/N is negligible at small loads), hertz, depth 1e-4 mm (linear kinematics: all lengths
// scale, only the ratio of global to local compliance matters, C_g dF/dalpha ~ 0.3 %). The
// local part must be Hertz's law with E* = E/(1 - nu^2), R = 12.7 mm (to the solver's tolerance:
// this checks the whole-shell force of the quarter model), and the force at the travel must be
// Hertz's F(h) within the 1 %. Measured: see the printout and docs/verification.md.
TEST(LocalIndentationVerification, ThickPlateLimit_Hertz_Within1Percent) {
  const double depth = 1e-4;
  const PathResult r = run_case(plate_case(50.0, quarter_mesh(1.0, 4.0), "hertz", depth, depth));
  ASSERT_FALSE(r.points.empty());
  const IndentationState& s = r.points.back().state;
  const double E = plate_hertz_modulus();
  const double local_ref = hertz_force(E, kSphere, s.local_indentation);
  const double travel_ref = hertz_force(E, kSphere, depth);
  std::cout << "thick plate at " << depth << " mm: F = " << s.force << " N, Hertz(alpha) "
            << local_ref << ", Hertz(h) " << travel_ref << " (" << s.force / travel_ref - 1
            << "), alpha/h = " << s.local_indentation / depth << "\n";
  const std::string source = "Hertz, E* = E/(1 - nu^2), R = 12.7 mm (point-loads.md 4.3)";
  test::record_verification(kTable, "thick plate t = 50 mm, h = 1e-4 mm: force vs Hertz F(alpha)",
                            local_ref, s.force, 1e-8, source);
  test::record_verification(kTable, "thick plate t = 50 mm: force vs Hertz F(h) at the travel",
                            travel_ref, s.force, 0.01, source + "; issue 7: 1 %");
  EXPECT_NEAR(s.force, local_ref, 1e-8 * local_ref);
  EXPECT_NEAR(s.force, travel_ref, 0.01 * travel_ref);
}

// ---------------------------------------------------------------------------------------------
// 3. Thin-shell limit: the plate t = 3.8 mm at 0.05 mm with Hertz laws of E_3 = 1e3 E and 1e4 E
// against `none` (the fast path). The difference is the local approach times the global
// stiffness, alpha ~ k^(-2/3): below 1e-3 relative for 1e4 E, and the ratio of the two differences
// 10^(2/3) = 4.64 to 5 % (the higher-order terms are O(alpha/h) ~ 0.5 %).
double force_at(IndentationFixture& f, double depth, int steps) {
  IndentationProblem& p = *f.problem;
  cont::Vector z = p.initial_point();
  for (int i = 1; i <= steps; ++i) {
    const cont::NewtonResult r = cont::solve_at(p, z, depth * i / steps, tight_kinsol_settings(p));
    EXPECT_TRUE(r.converged) << r.reason;
  }
  return p.evaluate(z, depth).force;
}

TEST(LocalIndentationVerification, ThinShellLimit_StiffTransverseModulusGivesNone) {
  const double depth = 0.05;
  const CaseFile c = isotropic_indentation_case(3.8, kPlateShell, quarter_mesh(1.0, 4.0), "linear",
                                                kSphere, "outer");
  IndentationFixture none(c);
  LinearIndentation fast(*none.problem);
  const double f_none = none.problem->evaluate(fast.solve(depth), depth).force;
  std::vector<double> differences;
  for (double scale : {1e3, 1e4}) {
    IndentationOptions o;
    o.local = hertz_law(kSphere, hertz_modulus(0, 0, scale * kIsotropicE, kIsotropicNu));
    IndentationFixture f(c, o);
    const double force = force_at(f, depth, 5);
    differences.push_back((f_none - force) / f_none);
    std::cout << "E_3 = " << scale << " E: F = " << force << " N, none " << f_none
              << " N, relative difference " << differences.back() << "\n";
  }
  EXPECT_GT(differences[1], 0);
  EXPECT_LT(differences[1], 1e-3);
  const double ratio = differences[0] / differences[1];
  std::cout << "  ratio " << ratio << " (k^(-2/3): " << std::pow(10.0, 2.0 / 3.0) << ")\n";
  test::record_verification_absolute(
      kTable, "thin-shell limit, plate t = 3.8 mm at 0.05 mm, E_3 = 1e4 E: (F_none - F) / F_none",
      0, differences[1], 1e-3, "the `none` option (fast path)");
  test::record_verification(kTable, "thin-shell limit: ratio of the differences at 1e3 E and 1e4 E",
                            std::pow(10.0, 2.0 / 3.0), ratio, 0.05, "alpha ~ k^(-2/3): 10^(2/3)");
  EXPECT_NEAR(ratio, std::pow(10.0, 2.0 / 3.0), 0.05 * std::pow(10.0, 2.0 / 3.0));
}

// ---------------------------------------------------------------------------------------------
// 4. The plate at 0.05 mm, hertz (E* = E/(1 - nu^2), R = 12.7 mm), linear kinematics.
// Reference: the Mindlin plate (point-loads.md 4.2) under the Hertzian pressure
// p = p0 (1 - r^2/c^2)^0.5 of radius c = (R alpha)^0.5 (point-loads.md 4.3), alpha the computed
// local approach. Its centre deflection is the integral of the load against the centre's
// influence function, w(r) per unit force of 4.2 (derived here):
//     w0 / F = a^2/(16 pi D) (1 + O(c^2/a^2)) + (ln(a/c) + 4/3 - ln 2) / (2 pi kGt),
// where 4/3 - ln 2 = (1/2) H_{3/2} replaces the uniform disc's 1/2 (the integral of
// [1 - (1 - rho^2)^1.5] / rho over (0, 1)); the O(c^2/a^2) bending term is below 1e-3 here.
// The shell: each gap carries Hertz's dent (hertz_dent.hpp), so inside the patch the shell's face
// meets a flat punch of radius c at depth h - alpha, and the shell's load spreads over the nodes
// within and around it once the mesh resolves c (0.46 mm here). A flat punch loads a
// shear-deformable plate towards its edge: the fine-mesh limit lies between the Hertzian
// reference and a ring load at c, whose Mindlin term is ln(a/c) without the 0.640, 2.7 % stiffer.
// A mesh coarser than the patch still carries the load on the apex node alone, a nodal load that
// acts as a disc of radius 0.19 e (docs/verification.md 3.3) and is too compliant by the Mindlin
// log term. Measured (F/w against the reference): e = 1 mm -2.77 % (one node in contact, as
// without the dent), e = 0.5 mm +1.43 % (the apex and the 0.5 mm ring; was -5.4 % with the
// uniform approach), e = 0.25 mm +1.62 % (long test). The 5 % is the tolerance. Also:
// where the apex is in contact (1 mm and 0.5 mm meshes) the travel is the apex deflection plus
// the local approach (the apex is inside the patch: its gap w + alpha - h is zero) to the
// solver's tolerance; on the 0.25 mm mesh the punch's load has moved to the rings at 0.25 and
// 0.5 mm and the apex lifts off by 3.9e-5 mm (a punch loads a shear-deformable plate at its edge),
// so only its gap's sign is checked there.
struct PlateAgainstMindlin {
  double stiffness = 0;  // F / apex w, N/mm
  double reference = 0;  // Mindlin under the Hertzian patch, N/mm
  double split = 0;      // apex w + alpha - h, mm: the apex's gap
  bool apex_in_contact = false;
};

PlateAgainstMindlin plate_against_mindlin(double element_size) {
  const double depth = 0.05, a = 25.0, t = 3.8;
  const CaseFile c = plate_case(t, quarter_mesh(element_size, 4.0), "hertz", depth, 0.01);
  IndentationSetup setup(c, 1);
  const PathResult r = run_indentation_path(setup);
  EXPECT_TRUE(r.completed) << r.reason;
  const IndentationState& s = r.points.back().state;
  const double kGt = setup.model.law.G(0, 0);
  const double D = kIsotropicE * t * t * t / (12 * (1 - kIsotropicNu * kIsotropicNu));
  const double c_hertz = std::sqrt(kSphere * s.local_indentation);
  const double compliance = a * a / (16 * kPi * D) +
                            (std::log(a / c_hertz) + 4.0 / 3.0 - std::log(2.0)) / (2 * kPi * kGt);
  PlateAgainstMindlin out{s.force / s.apex_deflection, 1 / compliance,
                          s.apex_deflection + s.local_indentation - depth, false};
  for (std::size_t i = 0; i < s.nodes.size(); ++i)
    if (s.nodes[i] == setup.model.apex_node())
      out.apex_in_contact = s.multipliers[i] > 1e-9 * s.force;
  std::cout << "plate, e = " << element_size << " mm, at " << depth << " mm: F = " << s.force
            << " N, apex w = " << s.apex_deflection << " mm, alpha = " << s.local_indentation
            << " mm (alpha/h = " << s.local_indentation / depth << "), F/h = " << s.force / depth
            << " N/mm, F/w = " << out.stiffness
            << " N/mm, Mindlin with the Hertz patch (c = " << c_hertz << " mm) " << out.reference
            << " N/mm (" << out.stiffness / out.reference - 1 << "), contact nodes "
            << s.contact_nodes << ", contact radius " << s.contact_radius << " mm, apex gap "
            << out.split << " mm\n";
  return out;
}

void expect_plate_within_5_percent(double element_size, const std::string& mesh) {
  const PlateAgainstMindlin p = plate_against_mindlin(element_size);
  test::record_verification(
      kTable, "issue's plate at h = 0.05 mm, " + mesh + " apex mesh: F / apex w (N/mm)",
      p.reference, p.stiffness, 0.05,
      "Mindlin plate under the Hertzian patch (point-loads.md 4.2, 4.3); "
      "issue 7: 5 %");
  EXPECT_NEAR(p.stiffness, p.reference, 0.05 * p.reference);
  EXPECT_GT(p.split, -1e-8 * 0.05);
  if (!p.apex_in_contact) return;
  test::record_verification_absolute(kTable, "same, " + mesh + ": apex w + alpha - h (mm)", 0.0,
                                     p.split, 1e-8 * 0.05, "the apex's gap is zero (in contact)");
  EXPECT_NEAR(p.split, 0.0, 1e-8 * 0.05);
}

TEST(LocalIndentationVerification, IsotropicClampedPlate_MindlinWithHertzPatch_Within5Percent) {
  expect_plate_within_5_percent(1.0, "1 mm");
}

// Was DISABLED_ (-5.4 %) while the local approach shifted the whole face uniformly.

TEST(LocalIndentationVerification,
     IsotropicClampedPlate_MindlinWithHertzPatch_Within5Percent_HalfMillimetreMesh) {
  expect_plate_within_5_percent(0.5, "0.5 mm");
}

// About 5 s: with SHELLINDENT_LONG_TESTS=1 only (the full verification study).
TEST(LocalIndentationVerification,
     IsotropicClampedPlate_MindlinWithHertzPatch_Within5Percent_QuarterMillimetreMesh) {
  if (!verification::long_tests_enabled()) GTEST_SKIP() << "set SHELLINDENT_LONG_TESTS=1 to run";
  expect_plate_within_5_percent(0.25, "0.25 mm");
}

// 4b. The quarter model with the dent: the axis lies on both symmetry planes, the dent radii are
// the same in every quadrant and the law sums the quarter's multipliers with the symmetry factor,
// so the quarter plate reports the whole plate: 1 mm mesh at h = 0.3 mm (patch radius 0.89 mm,
// the 1 mm ring in contact outside it), force, local approach, energy, contact area and apex
// deflection equal to the full model's to the solver's tolerance (1e-8 relative).
TEST(LocalIndentationVerification, HertzDent_QuarterPlateReportsTheWholePlate) {
  const double depth = 0.3;
  const auto run = [&](const std::string& symmetry) {
    const CaseFile c = isotropic_indentation_case(
        3.8, kPlateShell,
        "{size_apex: 1 mm, size_edge: 4 mm, refine_radius: 10 mm, symmetry: " + symmetry + "}",
        "linear", kSphere, "outer");
    IndentationOptions o;
    o.local = hertz_law(kSphere, plate_hertz_modulus());
    IndentationFixture f(c, o);
    cont::Vector z = f.problem->initial_point();
    for (int i = 1; i <= 6; ++i) {
      const cont::NewtonResult r =
          cont::solve_at(*f.problem, z, depth * i / 6, tight_kinsol_settings(*f.problem));
      EXPECT_TRUE(r.converged) << r.reason;
    }
    return f.problem->evaluate(z, depth);
  };
  const IndentationState full = run("full"), quarter = run("quarter");
  std::cout << "plate with the dent at " << depth << " mm: force " << quarter.force << " / "
            << full.force << " N, alpha " << quarter.local_indentation << " / "
            << full.local_indentation << " mm, contact radius " << quarter.contact_radius << " / "
            << full.contact_radius << " mm (patch " << std::sqrt(kSphere * full.local_indentation)
            << " mm)\n";
  const auto expect_same = [](double a, double b, const std::string& what) {
    test::record_verification(kTable,
                              "plate with the dent, h = 0.3 mm: quarter model vs full, " + what, b,
                              a, 1e-8, "the full model (a different model of the same shell)");
    EXPECT_NEAR(a, b, 1e-8 * std::abs(b)) << what;
  };
  expect_same(quarter.force, full.force, "force");
  expect_same(quarter.local_indentation, full.local_indentation, "local approach");
  expect_same(quarter.energy, full.energy, "strain energy");
  expect_same(quarter.contact_area, full.contact_area, "contact area");
  expect_same(quarter.apex_deflection, full.apex_deflection, "apex deflection");
  EXPECT_GT(full.contact_radius, std::sqrt(kSphere * full.local_indentation));
}

// ---------------------------------------------------------------------------------------------
// 5. Energy. The coupled system is stationary for U(x) + E_local(alpha), E_local = (2/5) k
// alpha^2.5, only where every node in contact has d g_i / d alpha = 1, i.e. lies inside the
// Hertzian patch. In general, along the path (s the symmetry factor, u_i' = du_i/dalpha the
// dent's rate at node i, ' = d/dh): each closed gap g_i = s_i(x) - t0 - h + u_i(alpha) = 0 gives
// G_i . x' = 1 - u_i' alpha', so dU/dh = s sum lambda_i G_i . x' = F - s alpha' sum lambda_i u_i'
// and, with dE_local/dh = k alpha^1.5 alpha' = F alpha' (the law: F = s sum lambda_i),
//     W = U + E_local - D,   D = integral of s sum_i lambda_i (1 - u_i') d alpha >= 0.
// D is the work the law credits to the nodes outside the patch for the approach alpha at the
// axis, of which their own face takes only u_i' d alpha: the local energy is then an upper bound
// of what the dent stores, and D is zero while the contact stays within the patch.
// F(h) ~ k h^1.5 at the start is not smooth at h = 0 (the trapezoidal rule's error there is
// O(dh^2.5) with a large constant), so each balance is checked from h0 to H with a fixed contact
// set, where F is smooth: W(h0 -> H) by the trapezoidal rule in h, D by the trapezoidal rule in
// alpha (u_i' recomputed from hertz_dent.hpp at each node's distance from the apex), and
// W - [U + E_local](h0 -> H) + D must fall at second order over 4, 8, 16 steps (observed order
// in [1.7, 2.3]). Measured: see the printout and docs/verification.md.
struct EnergyBalance {
  double work = 0;    // W(h0 -> H), N mm
  double stored = 0;  // [U + E_local](h0 -> H), N mm
  double defect = 0;  // D(h0 -> H), N mm
  int contact_nodes = 0;
  int outside = 0;  // nodes in contact outside the patch at H
};

// s sum_i lambda_i (1 - u_i') of a state (whole shell, N).
double defect_rate(const IndentationFixture& f, const IndentationState& s) {
  const Vector3d apex = f.model.mesh.nodes[f.model.apex_node()];
  const LocalContactLaw& law = f.problem->local_law();
  double sum = 0;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    const double r = (f.model.mesh.nodes[s.nodes[i]] - apex).head<2>().norm();
    sum += s.multipliers[i] * (1 - law.dent(r, s.local_indentation).rate);
  }
  return f.model.symmetry_factor * sum;
}

// The balance from h0 to H in n equal steps, starting from the converged z0 at h0.
EnergyBalance energy_balance(IndentationFixture& f, const cont::Vector& z0, double h0, double H,
                             int n) {
  IndentationProblem& p = *f.problem;
  cont::Vector z = z0;
  const IndentationState a = p.evaluate(z, h0);
  IndentationState b = a;
  EnergyBalance e;
  const double dh = (H - h0) / n;
  for (int i = 1; i <= n; ++i) {
    const double h = h0 + i * dh;
    const cont::NewtonResult r = cont::solve_at(p, z, h, tight_kinsol_settings(p));
    EXPECT_TRUE(r.converged) << r.reason;
    const IndentationState next = p.evaluate(z, h);
    e.work += 0.5 * (b.force + next.force) * dh;
    e.defect += 0.5 * (defect_rate(f, b) + defect_rate(f, next)) *
                (next.local_indentation - b.local_indentation);
    b = next;
  }
  e.stored = b.energy + b.local_energy - a.energy - a.local_energy;
  e.contact_nodes = b.contact_nodes;
  const LocalContactLaw& law = f.problem->local_law();
  const double a_patch = law.layer ? law.layer->contact_radius(b.local_indentation)
                                   : std::sqrt(law.radius * b.local_indentation);
  const Vector3d apex = f.model.mesh.nodes[f.model.apex_node()];
  for (std::size_t i = 0; i < b.nodes.size(); ++i)
    e.outside += b.multipliers[i] > 1e-9 * b.force &&  // in contact, as contact_nodes counts
                 (f.model.mesh.nodes[b.nodes[i]] - apex).head<2>().norm() > a_patch;
  return e;
}

// The observed orders of W - stored + D over 4, 8, 16 steps from h0 to H (recorded); returns
// the balances.
std::vector<EnergyBalance> expect_second_order_balance(IndentationFixture& f, double h0, double H,
                                                       const std::string& name) {
  IndentationProblem& p = *f.problem;
  cont::Vector z0 = p.initial_point();
  for (double h : {h0 / 2, h0}) {
    const cont::NewtonResult r = cont::solve_at(p, z0, h, tight_kinsol_settings(p));
    EXPECT_TRUE(r.converged) << r.reason;
  }
  std::vector<EnergyBalance> balances;
  std::vector<double> errors;
  for (int n : {4, 8, 16}) {
    balances.push_back(energy_balance(f, z0, h0, H, n));
    const EnergyBalance& e = balances.back();
    errors.push_back(e.work - e.stored + e.defect);
    std::cout << name << ", " << n << " steps: W = " << e.work << ", U + E_local " << e.stored
              << ", D " << e.defect << " N mm; W - U - E_local + D = " << errors.back()
              << " N mm; contact nodes " << e.contact_nodes << " (outside the patch " << e.outside
              << ")\n";
  }
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double order = std::log2(std::abs(errors[k - 1] / errors[k]));
    std::cout << "  observed order " << order << "\n";
    test::record_verification_absolute(
        kTable,
        name + ": order of W - U - E_local + D, " + std::to_string(4 << (k - 1)) + " -> " +
            std::to_string(4 << k) + " steps",
        2.0, order, 0.3, "trapezoidal rule, second order (W = U + E_local - D)");
    EXPECT_GE(order, 1.7);
    EXPECT_LE(order, 2.3);
  }
  return balances;
}

// The plate on a 2 mm mesh from 0.01 to 0.05 mm: the apex alone in contact, inside the
// patch, so D = 0 and W = U + E_local. Measured W - U - E_local = 0.0251, 0.00628, 0.00157 N mm
// (W = 17.48 N mm), orders 1.99, 2.00.
TEST(LocalIndentationVerification, IndenterWorkEqualsStrainPlusLocalEnergy_SecondOrder) {
  const CaseFile c = plate_case(3.8, quarter_mesh(2.0, 4.0), "hertz", 0.05, 0.05);
  IndentationOptions o;
  o.local = local_contact_law(c);
  IndentationFixture f(c, o);
  for (const EnergyBalance& e : expect_second_order_balance(f, 0.01, 0.05, "plate, 2 mm mesh")) {
    EXPECT_EQ(e.contact_nodes, 1);
    EXPECT_EQ(e.outside, 0);
    EXPECT_LT(std::abs(e.defect), 1e-12 * e.work);
  }
}

// The plate on a 0.5 mm mesh from 0.04 to 0.055 mm: the apex and the 0.5 mm ring in
// contact, the ring outside the patch (c = 0.44 to 0.46 mm), so D > 0: W = U + E_local - D at
// second order, and the naive balance W - U - E_local misses by D, far above the rule's error.
// Measured: D = 0.547 N mm of W = 11.0 N mm; W - U - E_local + D = see the printout.
TEST(LocalIndentationVerification, ContactOutsideThePatch_WorkEqualsStrainPlusLocalEnergyMinusD) {
  const CaseFile c = plate_case(3.8, quarter_mesh(0.5, 4.0), "hertz", 0.055, 0.055);
  IndentationOptions o;
  o.local = local_contact_law(c);
  IndentationFixture f(c, o);
  const std::vector<EnergyBalance> balances =
      expect_second_order_balance(f, 0.04, 0.055, "plate, 0.5 mm mesh, ring outside the patch");
  for (const EnergyBalance& e : balances) {
    EXPECT_EQ(e.contact_nodes, 3);
    EXPECT_EQ(e.outside, 2);
  }
  const EnergyBalance& e = balances.back();
  const double error = e.work - e.stored + e.defect;
  test::record_verification(
      kTable, "plate, 0.5 mm mesh, 0.04 -> 0.055 mm, 16 steps: U + E_local - W vs D (N mm)",
      e.defect, e.stored - e.work, 0.01,
      "the defect D of the nodes in contact outside the patch (derived)");
  EXPECT_GT(e.defect, 100 * std::abs(error));
  EXPECT_NEAR(e.stored - e.work, e.defect, 0.01 * e.defect);
}

// The anisotropic law of finite thickness (the paper's [0/90]2S, its upper half bonded to the
// mid-surface: F stiffens as the contact radius grows against the thickness) on the issue's
// plate, 2 mm mesh, 0.01 -> 0.05 mm: the apex alone in contact, so D = 0 and W = U + E_local with
// E_local = int F dalpha of the tabulated law, at the trapezoidal rule's second order.
TEST(LocalIndentationVerification, AnisotropicBondedLaw_WorkEqualsStrainPlusLocalEnergy) {
  CaseFile c = plate_case(3.8, quarter_mesh(2.0, 4.0), "none", 0.05, 0.05);
  c.laminate = testing::coarse_cap_case("linear", "[0/90]2S").laminate;
  c.contact.local = LocalContactModel::kAnisotropic;
  c.contact.local_support = LocalSupport::kBondedBase;
  IndentationOptions o;
  o.local = local_contact_law(c);
  ASSERT_NE(o.local.layer, nullptr);
  IndentationFixture f(c, o);
  for (const EnergyBalance& e : expect_second_order_balance(
           f, 0.01, 0.05, "plate [0/90]2S, anisotropic bonded, 2 mm mesh")) {
    EXPECT_EQ(e.contact_nodes, 1);
    EXPECT_LT(std::abs(e.defect), 1e-12 * e.work);
  }
}

// ---------------------------------------------------------------------------------------------
// 5b. The thin-layer `vam` law (c_L++ of the plate's section): the linear fast path and the
// KINSOL solve of the same problem agree (to the solvers' tolerance, 1e-8), and with a fixed
// contact set F is linear in h, so the trapezoidal work is exact: W = U + E_local to roundoff
// (1e-9 relative). The approach is c_L++ p at the apex node.
TEST(LocalIndentationVerification, ThinLayerVam_FastPathMatchesKinsolAndWorkIsExact) {
  const double depth = 0.05;
  const CaseFile c = plate_case(3.8, quarter_mesh(2.0, 4.0), "vam", depth, depth / 2);
  IndentationOptions o;
  o.local = local_contact_law(c);
  ASSERT_EQ(o.local.kind, LocalLawKind::kThinLayer);
  IndentationFixture f(c, o);
  IndentationProblem& p = *f.problem;
  LinearIndentation fast(p);
  const IndentationState half = p.evaluate(fast.solve(depth / 2), depth / 2);
  const IndentationState s = p.evaluate(fast.solve(depth), depth);
  cont::Vector z = p.initial_point();
  const cont::NewtonResult r = cont::solve_at(p, z, depth, tight_kinsol_settings(p));
  ASSERT_TRUE(r.converged) << r.reason;
  const IndentationState k = p.evaluate(z, depth);
  EXPECT_NEAR(s.force, k.force, 1e-8 * s.force);
  EXPECT_NEAR(s.local_indentation, k.local_indentation, 1e-8 * s.local_indentation);
  const double work = 0.5 * half.force * depth / 2 + 0.5 * (half.force + s.force) * depth / 2;
  std::cout << "vam plate at " << depth << " mm: c_L++ = " << o.local.compliance
            << " mm/MPa, F = " << s.force << " N, alpha(apex) = " << s.local_indentation
            << " mm, W = " << work << ", U + E_local = " << s.energy + s.local_energy << " N mm\n";
  test::record_verification(kTable,
                            "`vam` thin layer, plate at 0.05 mm: force, fast path vs KINSOL",
                            k.force, s.force, 1e-8, "KINSOL solve of the same problem");
  test::record_verification(kTable, "`vam` thin layer: W vs U + E_local (F linear in h: exact)",
                            s.energy + s.local_energy, work, 1e-9, "energy balance (exact)");
  EXPECT_EQ(half.contact_nodes, s.contact_nodes);
  EXPECT_GT(s.local_indentation, 0);
  EXPECT_NEAR(work, s.energy + s.local_energy, 1e-9 * work);
}

// ---------------------------------------------------------------------------------------------
// 6. A Hertz-type law needs a sphere: the case-file reader refuses another shape with an input
// error naming contact.local, its value and its line.
TEST(LocalIndentationVerification, HertzWithFlatPunch_IsAnInputErrorNamingContactLocal) {
  const std::string yaml =
      "material: {type: isotropic, E: 70000 MPa, nu: 0.3}\n"
      "laminate: {layup: \"[0]\", ply_thickness: 3.8 mm}\n"
      "indenter: {shape: flat_punch, radius: 5 mm}\n"
      "contact: {local: yang_sun}\n";
  try {
    parse_case_file(yaml, "punch.yaml");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().key, "contact.local");
    EXPECT_EQ(e.where().value, "yang_sun");
    EXPECT_EQ(e.where().line, 4);
  }
}

}  // namespace
}  // namespace si
