// Verification of the rigid-indenter contact solve (issue 4 acceptance criteria), each against an
// independent reference:
//  1. clamped isotropic plate, small sphere on the mid-surface, linear kinematics: the deflection
//     away from the contact (Kirchhoff + the Reissner-Mindlin log term, point-loads.md 4.2) and
//     the force per depth, whose mesh dependence is exactly the Mindlin log term;
//  2. shallow isotropic cap, small sphere: Reissner's (1946) apex stiffness (point-loads.md 4.1);
//  3. the contact pressure has the symmetries of mesh and lay-up (exact property);
//  4. indenter work (trapezoidal rule over depth) = strain energy, error O(dh^2);
//  5. bad indenters: input errors naming the key and value.
// Numbers quoted in comments were measured on 2026-11-22 (Release, 2 vCPU); see
// docs/verification.md section 3.2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "../verification_record.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "indentation_test_support.hpp"

namespace si {
namespace {

using testing::coarse_cap_case;
using testing::IndentationFixture;
using testing::isotropic_indentation_case;
using testing::kIsotropicE;
using testing::kIsotropicNu;
using testing::tight_kinsol_settings;

// One assembly thread: the CI machine is shared, and OpenMP threads on busy cores slow the
// nonlinear solves down by several times.
IndentationOptions one_thread() {
  IndentationOptions o;
  o.threads = 1;
  return o;
}

// The paper's plate and cap geometry (paper-notes P8): base radius 25 mm, cap radius 80.9 mm.
constexpr double kBaseRadius = 25.0;
constexpr double kCapRadius = 80.9;
const char* const kPlateShell = "{type: flat_circular_plate, radius: 25 mm, edge: clamped}";
const char* const kCapShell =
    "{type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}";

std::string quarter_mesh(double size_apex, double size_edge) {
  return "{size_apex: " + std::to_string(size_apex) +
         " mm, size_edge: " + std::to_string(size_edge) +
         " mm, refine_radius: 10 mm, symmetry: quarter}";
}

double plate_rigidity(double t) {
  return kIsotropicE * t * t * t / (12 * (1 - kIsotropicNu * kIsotropicNu));
}

// The node on the +x axis (y = 0) closest to x.
int node_on_x_axis(const Mesh& mesh, double x) {
  int best = -1;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vector3d& p = mesh.nodes[n];
    if (std::abs(p.y()) > 1e-12 || p.x() < 0) continue;
    if (best < 0 || std::abs(p.x() - x) < std::abs(mesh.nodes[best].x() - x)) best = n;
  }
  return best;
}

// ---------------------------------------------------------------------------------------------
// 1. Clamped plate (a = 25 mm, t = 3.8 mm, E = 70 GPa, nu = 0.3), rigid sphere of radius 1 mm on
// the mid-surface, linear kinematics (fast path), depth 0.01 mm (w0 / t = 0.003).
//
// What is a fair discrete comparison. The sphere is small enough that at this depth it touches
// one node only (checked): the discrete contact is a point load P at the apex. For such a load
// point-loads.md 4.2 gives, for the Reissner-Mindlin plate (kGt = the section's shear stiffness),
//     w(r) = P/(16 pi D) [a^2 - r^2 + 2 r^2 ln(r/a)] + P/(2 pi kGt) ln(a/r),
// exact away from the load; at the load itself w is log-singular, and a load spread over a disc
// of radius c gives w0 = P a^2/(16 pi D) + P/(2 pi kGt) (ln(a/c) + 1/2). The depth (= w0 here:
// contact on the mid-surface at the apex node) therefore does not converge under refinement,
// and a nodal load acts as a disc of radius c = beta e (e the element size at the apex). Two
// checks follow: (a) w(r)/P at r >= 2 t against the exact formula, converging at second order;
// (b) the force per depth: its change between meshes e and e/2 must be the Mindlin log term,
// h/P (e/2) - h/P (e) = ln 2 / (2 pi kGt), i.e. beta is mesh independent and
// P/h -> 1 / (a^2/(16 pi D) + (ln(a/(beta e)) + 1/2) / (2 pi kGt)).
struct PlateIndentation {
  double element_size = 0;
  double force = 0, depth = 0, kGt = 0;
  int contact_nodes = 0;
  std::vector<double> radii, deflections;  // along the x axis at 2 t, 3 t, a/2
};

PlateIndentation indent_clamped_plate(double element_size) {
  const double t = 3.8, depth = 0.01;
  IndentationFixture f(isotropic_indentation_case(
      t, kPlateShell, quarter_mesh(element_size, 2 * element_size), "linear", 1.0, "mid"));
  LinearIndentation fast(*f.problem);
  const cont::Vector z = fast.solve(depth);
  const IndentationState s = f.problem->evaluate(z, depth);
  const std::vector<NodeState> states = f.problem->node_states(z);
  PlateIndentation out;
  out.element_size = element_size;
  out.force = s.force;
  out.depth = depth;
  out.kGt = f.model.law.G(0, 0);
  out.contact_nodes = s.contact_nodes;
  for (double r : {2 * t, 3 * t, kBaseRadius / 2}) {
    const int n = node_on_x_axis(f.model.mesh, r);
    out.radii.push_back(f.model.mesh.nodes[n].x());
    out.deflections.push_back(-states[n].u.z());
  }
  return out;
}

// point-loads.md 4.2, per unit force.
double plate_deflection_per_force(double r, double t, double kGt) {
  const double a = kBaseRadius;
  return (a * a - r * r + 2 * r * r * std::log(r / a)) / (16 * kPi * plate_rigidity(t)) +
         std::log(a / r) / (2 * kPi * kGt);
}

class ClampedPlateSphere : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    coarse_ = new PlateIndentation(indent_clamped_plate(1.0));
    fine_ = new PlateIndentation(indent_clamped_plate(0.5));
  }
  static void TearDownTestSuite() {
    delete coarse_;
    delete fine_;
  }
  static PlateIndentation* coarse_;
  static PlateIndentation* fine_;
};
PlateIndentation* ClampedPlateSphere::coarse_ = nullptr;
PlateIndentation* ClampedPlateSphere::fine_ = nullptr;

// (a) Measured relative errors at r = 2t, 3t, a/2: e = 1 mm: -6.5e-4, -9.3e-4, -1.1e-3;
// e = 0.5 mm: -1.4e-4, -2.2e-4, -2.6e-4 (e = 0.25 mm: -3.5e-5, -5.3e-5, -6.3e-5): second order.
// Tolerances: the finer mesh within 0.1 % (the reference is exact for the model; 0.1 % is the
// second-order prediction from the coarser mesh, 1.1e-3 / 4, with a factor 4 margin), and the
// error must fall by at least 3 per halving (second order gives 4).
TEST_F(ClampedPlateSphere, DeflectionAwayFromContact_KirchhoffPlusMindlinLog_PointLoads42) {
  const double t = 3.8;
  for (const PlateIndentation* run : {coarse_, fine_}) {
    EXPECT_EQ(run->contact_nodes, 1) << "the sphere must act as a point load here";
    EXPECT_GT(run->force, 0);
  }
  for (std::size_t i = 0; i < fine_->radii.size(); ++i) {
    const auto error = [&](const PlateIndentation& run) {
      const double ref = run.force * plate_deflection_per_force(run.radii[i], t, run.kGt);
      return (run.deflections[i] - ref) / ref;
    };
    const double e_coarse = error(*coarse_), e_fine = error(*fine_);
    std::cout << "clamped plate + sphere: w(r = " << fine_->radii[i] << ") error " << e_fine
              << " (e = 0.5 mm), " << e_coarse << " at r = " << coarse_->radii[i]
              << " (e = 1 mm)\n";
    EXPECT_LT(std::abs(e_fine), 1e-3);
    const double ref_fine =
        fine_->force * plate_deflection_per_force(fine_->radii[i], t, fine_->kGt);
    char check[80];
    std::snprintf(check, sizeof check,
                  "clamped plate + 1 mm sphere, w at r = %.2f mm (0.5 mm mesh)", fine_->radii[i]);
    test::record_verification("contact-closed-forms", check, ref_fine, fine_->deflections[i], 1e-3,
                              "Kirchhoff + Mindlin log term (point-loads.md 4.2)");
    EXPECT_LT(std::abs(e_fine), std::abs(e_coarse) / 3);
  }
}

// (b) Measured: P/h = 22308.1 N/mm (e = 1 mm), 21696.4 (0.5), 21129.7 (0.25); the compliance
// steps are 1.0304 and 1.0079 times ln 2/(2 pi kGt) (kGt = 89952 N/mm); beta = c/e = 0.194,
// 0.190, 0.189; the Kirchhoff value alone would be 16 pi D / a^2 = 28289 N/mm. Tolerance 5 % of
// the log term for the step 1 -> 0.5 mm: the part of the compliance that is not the log term is
// the discretisation error of the point-load solution, which falls at second order (a); its
// measured size on the 1 mm mesh, 3 %, bounds it.
TEST_F(ClampedPlateSphere, ForcePerDepth_ChangesWithTheMeshByTheMindlinLogTerm_PointLoads42) {
  const double log_term = std::log(2.0) / (2 * kPi * fine_->kGt);
  const double step =
      fine_->depth / fine_->force - coarse_->depth / coarse_->force;  // compliance, mm/N
  const double t = 3.8;
  const double kirchhoff = kBaseRadius * kBaseRadius / (16 * kPi * plate_rigidity(t));
  const double beta =
      std::exp(0.5 - (fine_->depth / fine_->force - kirchhoff) / (1 / (2 * kPi * fine_->kGt))) *
      kBaseRadius / fine_->element_size;
  std::cout << "clamped plate + sphere: P/h = " << coarse_->force / coarse_->depth << ", "
            << fine_->force / fine_->depth << " N/mm (e = 1, 0.5 mm); compliance step / (ln 2 /"
            << " (2 pi kGt)) = " << step / log_term << "; equivalent load radius " << beta
            << " e; Kirchhoff stiffness " << 1 / kirchhoff << "\n";
  EXPECT_NEAR(step, log_term, 0.05 * log_term);
  test::record_verification(
      "contact-closed-forms", "clamped plate + sphere: compliance change 1 -> 0.5 mm mesh (mm/N)",
      log_term, step, 0.05, "Mindlin log term ln 2 / (2 pi kGt) (point-loads.md 4.2)");
  // The stiffness lies below the Kirchhoff point-load stiffness by the shear term.
  EXPECT_LT(fine_->force / fine_->depth, 1 / kirchhoff);
}

// ---------------------------------------------------------------------------------------------
// 2. Reissner (1946), point-loads.md 4.1: k = 4 E t^2 / (R sqrt(3 (1 - nu^2))) for a shallow
// isotropic cap with supports several bending lengths l = 0.5501 sqrt(R t) away and a contact
// radius << l. Here t = 0.2 mm: l = 2.21 mm, base radius 11.3 l; sphere radius 1 mm on the outer
// face, linear kinematics, depth 0.02 mm = 0.1 t; one node in contact (checked). Measured
// k = 84.459 N/mm vs 83.789 (+0.80 %) with 0.5 mm elements at the apex (+0.19 % with 0.25 mm).
// Tolerance 5 %: point-loads.md 4.1, "within a few percent".
TEST(ContactVerification, ShallowCapSmallSphere_LinearApexStiffness_Reissner1946) {
  const double t = 0.2, depth = 0.02;
  IndentationFixture f(
      isotropic_indentation_case(t, kCapShell, quarter_mesh(0.5, 2.0), "linear", 1.0, "outer"));
  LinearIndentation fast(*f.problem);
  const IndentationState s = f.problem->evaluate(fast.solve(depth), depth);
  const double k = s.force / depth;
  const double k_ref =
      4 * kIsotropicE * t * t / (kCapRadius * std::sqrt(3 * (1 - kIsotropicNu * kIsotropicNu)));
  std::cout << "shallow cap t = 0.2 mm, 1 mm sphere: F/h = " << k << " N/mm, Reissner " << k_ref
            << ", error " << (k - k_ref) / k_ref << "\n";
  EXPECT_EQ(s.contact_nodes, 1);
  EXPECT_NEAR(k, k_ref, 0.05 * k_ref);
  test::record_verification("contact-closed-forms",
                            "shallow cap t = 0.2 mm, 1 mm sphere: linear apex stiffness (N/mm)",
                            k_ref, k, 0.05, "Reissner 1946 (point-loads.md 4.1)");
}

// ---------------------------------------------------------------------------------------------
// 3. Symmetry of the contact pressure. A plane map M (x, y) -> M (x, y), z unchanged, that maps
// the mesh onto itself and leaves the section invariant maps the solution onto itself, so the
// pressure at node n equals that at its image. Full models (no symmetry built in).
struct PlaneMap {
  std::string name;
  Eigen::Matrix2d m;
};

std::vector<PlaneMap> square_symmetries() {
  const auto map = [](const std::string& name, double a, double b, double c, double d) {
    Eigen::Matrix2d m;
    m << a, b, c, d;
    return PlaneMap{name, m};
  };
  return {map("mirror x", -1, 0, 0, 1),      map("mirror y", 1, 0, 0, -1),
          map("rotation 180", -1, 0, 0, -1), map("diagonal", 0, 1, 1, 0),
          map("antidiagonal", 0, -1, -1, 0), map("rotation 90", 0, -1, 1, 0)};
}

// node -> its image under m (positions matched to 1e-9 mm); empty if m does not map the mesh
// onto itself.
std::vector<int> node_image(const Mesh& mesh, const Eigen::Matrix2d& m) {
  std::vector<int> out(mesh.num_nodes(), -1);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    Vector3d q = mesh.nodes[n];
    q.head<2>() = m * q.head<2>();
    for (int k = 0; k < mesh.num_nodes() && out[n] < 0; ++k)
      if ((mesh.nodes[k] - q).norm() < 1e-9) out[n] = k;
    if (out[n] < 0) return {};
  }
  return out;
}

// Pressure at the indentation depth, reached by KINSOL in `steps` equal steps.
struct PressureField {
  std::map<int, double> pressure;  // candidate node -> MPa
  double max_pressure = 0;
  int contact_nodes = 0;
  IndentationState state;
};

PressureField pressure_at(IndentationFixture& f, double depth, int steps) {
  IndentationProblem& p = *f.problem;
  cont::Vector z = p.initial_point();
  for (int i = 1; i <= steps; ++i) {
    const cont::NewtonResult r = cont::solve_at(p, z, depth * i / steps, tight_kinsol_settings(p));
    EXPECT_TRUE(r.converged) << r.reason;
  }
  const IndentationState s = p.evaluate(z, depth);
  PressureField out;
  out.state = s;
  out.contact_nodes = s.contact_nodes;
  for (std::size_t i = 0; i < s.nodes.size(); ++i) {
    out.pressure[s.nodes[i]] = s.pressures[i];
    out.max_pressure = std::max(out.max_pressure, std::abs(s.pressures[i]));
  }
  return out;
}

// Largest |p(n) - p(image of n)| / max p; infinity when the candidate set is not mapped onto
// itself; NaN when m is not a symmetry of the mesh.
double pressure_asymmetry(const Mesh& mesh, const PressureField& field, const PlaneMap& map) {
  const std::vector<int> image = node_image(mesh, map.m);
  if (image.empty()) return std::nan("");
  double worst = 0;
  for (const auto& [node, value] : field.pressure) {
    const auto it = field.pressure.find(image[node]);
    if (it == field.pressure.end()) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, std::abs(value - it->second));
  }
  return worst / field.max_pressure;
}

// Checks the maps named in `exact` to 1e-12 of the largest pressure (round-off: the solve of a
// symmetric problem from a symmetric start keeps the symmetry up to round-off) and returns the
// asymmetry under every map, printed.
std::map<std::string, double> check_symmetries(IndentationFixture& f, const std::string& label,
                                               const std::vector<std::string>& exact) {
  const PressureField field = pressure_at(f, 1.5, 3);
  EXPECT_GT(field.contact_nodes, 1);  // a pressure distribution, not a point
  std::map<std::string, double> out;
  std::cout << label << ", h = 1.5 mm, " << field.contact_nodes << " nodes in contact:";
  for (const PlaneMap& map : square_symmetries()) {
    out[map.name] = pressure_asymmetry(f.model.mesh, field, map);
    std::cout << " " << map.name << " " << out[map.name] << ";";
  }
  std::cout << "\n";
  for (const std::string& name : exact) {
    EXPECT_LT(out.at(name), 1e-12) << label << ": " << name;
    test::record_verification_absolute("contact-closed-forms",
                                       label + ": pressure asymmetry / max p, " + name, 0.0,
                                       out.at(name), 1e-12, "exact symmetry");
  }
  return out;
}

const char* const kFullCoarseMesh =
    "{size_apex: 2 mm, size_edge: 4 mm, refine_radius: 10 mm, symmetry: full}";

// Isotropic plate, sphere 12.7 mm on the mid-surface, nonlinear kinematics: every symmetry of
// the square O-grid is one of the problem. Measured: all six maps below 7e-15.
TEST(ContactVerification, IsotropicPlate_ContactPressureHasTheMeshSymmetries) {
  IndentationFixture f(
      isotropic_indentation_case(3.8, kPlateShell, kFullCoarseMesh, "nonlinear", 12.7, "mid"),
      one_thread());
  check_symmetries(
      f, "isotropic plate",
      {"mirror x", "mirror y", "rotation 180", "diagonal", "antidiagonal", "rotation 90"});
}

// Isotropic cap (t = 3.8 mm, sphere 12.7 mm on the outer face), nonlinear kinematics: the two
// mirrors and the half turn hold to round-off (measured <= 1.4e-14).
TEST(ContactVerification, IsotropicCap_ContactPressureHasTheMirrorSymmetries) {
  IndentationFixture f(
      isotropic_indentation_case(3.8, kCapShell, kFullCoarseMesh, "nonlinear", 12.7, "outer"),
      one_thread());
  check_symmetries(f, "isotropic cap", {"mirror x", "mirror y", "rotation 180"});
}

// The diagonal mirrors and the quarter turn are symmetries of the cap's mesh (nodes and
// directors map to within 1.3e-14) and of the isotropic section, so they should hold to
// round-off too. Measured with mitc4: 5.0e-8 of the largest pressure (nonlinear; 8.7e-8 linear).
// The source is the element, not the contact: a static apex force on the same cap without
// contact (run_static, linear) breaks the diagonal symmetry of w by 1.2e-7 with mitc4 and by
// 2e-15 with mitc4-plain, so it is the EAS-4 membrane on warped elements that depends on the
// element's orientation; with mitc4-plain the contact pressure holds every map to round-off
// (next test). Kept at the exact tolerance and disabled (reported to the element's owner).
TEST(ContactVerification, DISABLED_IsotropicCap_ContactPressureHasTheDiagonalSymmetries) {
  IndentationFixture f(
      isotropic_indentation_case(3.8, kCapShell, kFullCoarseMesh, "nonlinear", 12.7, "outer"),
      one_thread());
  check_symmetries(f, "isotropic cap", {"diagonal", "antidiagonal", "rotation 90"});
}

// The same cap with mitc4-plain (no EAS membrane): every map of the O-grid holds to round-off.
TEST(ContactVerification, IsotropicCapPlainMitc4_ContactPressureHasTheMeshSymmetries) {
  IndentationFixture f(
      isotropic_indentation_case(
          3.8, kCapShell,
          "{element: mitc4-plain, size_apex: 2 mm, size_edge: 4 mm, refine_radius: 10 mm}",
          "nonlinear", 12.7, "outer"),
      one_thread());
  check_symmetries(
      f, "isotropic cap, mitc4-plain",
      {"mirror x", "mirror y", "rotation 180", "diagonal", "antidiagonal", "rotation 90"});
}

// [0]8 (paper material): orthotropic with the axes along x and y, so the x and y mirrors (and
// the half turn) are symmetries, measured <= 5.6e-15; the diagonal mirror is not (it swaps
// E_L and E_T), measured 8.4e-2, which also shows that the check can fail.
TEST(ContactVerification, UnidirectionalCap_ContactPressureHasTheMirrorSymmetriesOnly) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0]8"), one_thread());
  const std::map<std::string, double> a =
      check_symmetries(f, "[0]8 cap", {"mirror x", "mirror y", "rotation 180"});
  EXPECT_GT(a.at("diagonal"), 1e-3);
}

// The quarter model (symmetry_factor 4, symmetry planes as supports) reports the whole shell's
// values: force, reaction, energy, contact area and radius, apex deflection and the pressures
// equal those of the full model, whose mesh has the same nodes in the quarter (exact property;
// tolerance 1e-10 relative: the two solves differ in size and ordering, round-off and the
// 1e-12 Newton tolerance).
TEST(ContactVerification, QuarterModelReportsTheWholeShell) {
  const auto run = [](const std::string& symmetry) {
    IndentationFixture f(
        isotropic_indentation_case(3.8, kCapShell,
                                   "{size_apex: 2 mm, size_edge: 4 mm, refine_radius: 10 mm, "
                                   "symmetry: " +
                                       symmetry + "}",
                                   "nonlinear", 12.7, "outer"),
        one_thread());
    return pressure_at(f, 1.5, 3);
  };
  const PressureField full_field = run("full"), quarter_field = run("quarter");
  const IndentationState& full = full_field.state;
  const IndentationState& quarter = quarter_field.state;
  std::cout << "quarter vs full cap: force " << quarter.force << " / " << full.force << ", energy "
            << quarter.energy << " / " << full.energy << ", area " << quarter.contact_area << " / "
            << full.contact_area << "\n";
  const auto expect_same = [](double a, double b, const char* what) {
    EXPECT_NEAR(a, b, 1e-10 * std::abs(b)) << what;
    test::record_verification(
        "contact-closed-forms",
        std::string("isotropic cap, h = 1.5 mm: quarter model vs full, ") + what, b, a, 1e-10,
        "the full model (a different model of the same shell)");
  };
  expect_same(quarter.force, full.force, "force");
  expect_same(quarter.reaction, full.reaction, "reaction");
  expect_same(quarter.energy, full.energy, "energy");
  expect_same(quarter.contact_area, full.contact_area, "contact area");
  expect_same(quarter.contact_radius, full.contact_radius, "contact radius");
  expect_same(quarter.apex_deflection, full.apex_deflection, "apex deflection");
  expect_same(quarter_field.max_pressure, full_field.max_pressure, "largest pressure");
}

// ---------------------------------------------------------------------------------------------
// 4. Work of the indenter W = int_0^H F dh (trapezoidal rule over the computed depths) against
// the strain energy U(H): equal up to the rule's error, -H dh^2 / 12 <F''> for a smooth F.
// Contact-set changes make F only piecewise smooth (a kink in F each time a node comes into
// contact), so the order is measured where it is clean and the kinks are handled separately.

// Whole-shell contact force at z: the sum of the multipliers (IndentationState::force) without
// the assembly that evaluate() does.
double contact_force(const IndentationProblem& p, const cont::Vector& z) {
  return z.tail(static_cast<Eigen::Index>(p.candidates().size())).sum() * p.model().symmetry_factor;
}

// Trapezoidal work and final energy of a KINSOL run to `depth` in n equal steps.
double trapezoid_error(IndentationFixture& f, double depth, int n) {
  IndentationProblem& p = *f.problem;
  cont::Vector z = p.initial_point();
  double work = 0, previous = 0;
  for (int i = 1; i <= n; ++i) {
    const cont::NewtonResult r = cont::solve_at(p, z, depth * i / n, tight_kinsol_settings(p));
    EXPECT_TRUE(r.converged) << r.reason;
    const double F = contact_force(p, z);
    work += 0.5 * (previous + F) * depth / n;
    previous = F;
  }
  const IndentationState s = p.evaluate(z, depth);
  EXPECT_EQ(s.contact_nodes, 1);  // the contact set did not change
  std::cout << "  " << n << " steps: W = " << work << ", U = " << s.energy << " N mm\n";
  return work - s.energy;
}

// Nonlinear kinematics, [0/90]2S cap (quarter model: specially orthotropic), sphere 12.7 mm on
// the outer face, to 0.45 mm: one node in contact all the way (the set grows near 0.47 mm), so F
// is smooth and the error must fall at second order: observed order in [1.7, 2.3]. Measured:
// W - U = -5.486, -1.372, -0.343 N mm with 2, 4, 8 steps (U = 1.9e3 N mm), orders 1.9990 and
// 1.9998. A coarser mesh than elsewhere (3 mm at the apex): the identity holds on any mesh.
TEST(ContactVerification, IndenterWorkEqualsStrainEnergy_SecondOrderInTheStep_Nonlinear) {
  IndentationFixture f(coarse_cap_case("nonlinear", "[0/90]2S", "quarter", 3.0, 6.0), one_thread());
  const double depth = 0.45;
  std::vector<double> errors;
  for (int n : {2, 4, 8}) errors.push_back(trapezoid_error(f, depth, n));
  std::cout << "nonlinear cap, work - energy to " << depth << " mm: " << errors[0] << ", "
            << errors[1] << ", " << errors[2] << " N mm (2, 4, 8 steps)\n";
  for (std::size_t k = 1; k < errors.size(); ++k) {
    const double order = std::log2(std::abs(errors[k - 1] / errors[k]));
    std::cout << "  observed order " << order << "\n";
    EXPECT_GE(order, 1.7);
    EXPECT_LE(order, 2.3);
    test::record_verification_absolute("contact-closed-forms",
                                       "nonlinear [0/90]2S cap: order of W - U, steps " +
                                           std::to_string(1 << k) + " -> " + std::to_string(2 << k),
                                       2.0, order, 0.3, "trapezoidal rule, second order (W = U)");
  }
}

// Linear kinematics (fast path), [0/90]2S cap, to 1.5 mm: four contact-set changes on the way
// (1 -> 3 -> 5 -> 9 nodes). F is piecewise linear in h (the LCP solution is), so the trapezoidal
// rule is exact on every interval without a kink, and an interval with a kink at fraction s
// where the slope jumps by J >= 0 contributes J dh^2 s (1 - s) / 2. Hence the exact bound
//     0 <= W - U <= dh^2 / 8 * (F'(H-) - F'(0+))
// (the slope only changes at kinks), i.e. second order with a constant that depends on where
// the kinks fall. Checked for 6 to 96 steps, and the mean observed order over the four
// halvings in [1.7, 2.3]. Measured: see the printout (docs/verification.md 3.2).
TEST(ContactVerification, IndenterWorkEqualsStrainEnergy_SecondOrderInTheStep_Linear) {
  IndentationFixture f(coarse_cap_case("linear", "[0/90]2S"));
  IndentationProblem& p = *f.problem;
  LinearIndentation fast(p);
  const double depth = 1.5, delta = 1e-4;
  const auto force = [&](double h) { return contact_force(p, fast.solve(h)); };
  const double slope_jumps = (force(depth) - force(depth - delta)) / delta - force(delta) / delta;
  const double energy = p.evaluate(fast.solve(depth), depth).energy;
  std::vector<double> errors;
  for (int n : {6, 12, 24, 48, 96}) {
    const double dh = depth / n;
    double work = 0, previous = 0;
    for (int i = 1; i <= n; ++i) {
      const double F = force(i * dh);
      work += 0.5 * (previous + F) * dh;
      previous = F;
    }
    errors.push_back(work - energy);
    std::cout << "linear cap, " << n << " steps: W - U = " << work - energy << " N mm, bound "
              << dh * dh / 8 * slope_jumps << "\n";
    EXPECT_GE(work - energy, -1e-10 * energy);
    EXPECT_LE(work - energy, dh * dh / 8 * slope_jumps);
  }
  const double order = std::log2(errors.front() / errors.back()) / 4;
  std::cout << "  mean observed order " << order << " (U = " << energy << " N mm)\n";
  EXPECT_GE(order, 1.7);
  EXPECT_LE(order, 2.3);
  test::record_verification_absolute("contact-closed-forms",
                                     "linear [0/90]2S cap: mean order of W - U, 6 -> 96 steps", 2.0,
                                     order, 0.3, "trapezoidal rule, second order (W = U)");
}

// ---------------------------------------------------------------------------------------------
// 5. Bad indenters. The problem's constructor refuses an indenter that never touches the shell
// and one that starts inside it; the case-file reader refuses a non-positive radius and an
// unknown shape. Each message must name the key and the value.

void expect_input_error(const std::function<void()>& run, const std::string& key,
                        const std::string& value, const std::string& reason_part) {
  try {
    run();
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().key, key);
    EXPECT_EQ(e.where().value, value);
    const std::string message = e.what();
    EXPECT_NE(message.find(key), std::string::npos) << message;
    EXPECT_NE(message.find("'" + value + "'"), std::string::npos) << message;
    EXPECT_NE(message.find(reason_part), std::string::npos) << message;
  }
}

// A sphere of radius 2 mm posed at `position` travelling along `direction` over a coarse plate.
void indent_plate_from(const Vector3d& position, const Vector3d& direction) {
  const CaseFile c =
      isotropic_indentation_case(1.0, kPlateShell, quarter_mesh(2.0, 4.0), "linear", 2.0, "mid");
  const ShellModel model = build_shell_model(c);
  IndenterPose pose;
  pose.position = position;
  pose.direction = direction;
  const std::unique_ptr<Indenter> indenter = make_indenter(c.indenter, pose);
  IndentationProblem problem(model, *indenter, direction, IndentationOptions{});
}

TEST(ContactVerification, IndenterBesideTheShell_IsAnInputError) {
  expect_input_error(
      [] {
        indent_plate_from({40, 0, 10}, {0, 0, -1});
      },
      "indenter", "sphere", "never touches the shell");
}

TEST(ContactVerification, IndenterMovingAway_IsAnInputError) {
  expect_input_error(
      [] {
        indent_plate_from({0, 0, 10}, {0, 0, 1});
      },
      "indenter", "sphere", "never touches the shell");
}

TEST(ContactVerification, IndenterStartingInsideTheShell_IsAnInputError) {
  expect_input_error(
      [] {
        indent_plate_from({0, 0, 1}, {0, 0, -1});
      },
      "indenter", "sphere", "starts inside the shell");
}

std::string plate_case_with_indenter(const std::string& indenter) {
  return "material: {type: isotropic, E: 70000 MPa, nu: 0.3}\n"
         "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n"
         "shell: {type: flat_circular_plate, radius: 25 mm, edge: clamped}\n"
         "indenter: " +
         indenter + "\n";
}

TEST(ContactVerification, IndenterRadiusZeroOrNegative_IsAnInputError) {
  for (const std::string radius : {"0 mm", "-3 mm"})
    expect_input_error(
        [&] {
          parse_case_file(plate_case_with_indenter("{shape: sphere, radius: " + radius + "}"),
                          "bad.yaml");
        },
        "indenter.radius", radius, "");
  expect_input_error(
      [] {
        parse_case_file(plate_case_with_indenter("{shape: flat_punch, radius: -1 mm}"), "bad.yaml");
      },
      "indenter.radius", "-1 mm", "");
}

TEST(ContactVerification, IndenterUnknownShape_IsAnInputError) {
  expect_input_error(
      [] { parse_case_file(plate_case_with_indenter("{shape: cone, radius: 5 mm}"), "bad.yaml"); },
      "indenter.shape", "cone", "sphere");
}

}  // namespace
}  // namespace si
