// Issue 16 stage 2: damage onset along the depth path, against independent references:
//  * linear kinematics with one node in contact: every displacement, strain, recovered stress is
//    proportional to the depth and the indices are homogeneous of degree 1 in the stress, so each
//    monitored index is index(h_ref) h / h_ref exactly, and the onset lies at h_ref / index(h_ref)
//    (closed form) - located to the event tolerance;
//  * the threshold equals damage/delamination_threshold's value on the laminate's D;
//  * the depth at an impact energy solves the trapezoidal work of path.csv's columns
//    (computed here from depth and force), an energy above the path is beyond it;
//  * on the nonlinear cap (continuation), the located onset's index is 1 and its work maps back
//    to its depth through the impact-energy interpolation.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "analysis/indentation_run.hpp"
#include "analysis/local_contact.hpp"
#include "analysis/path_columns.hpp"
#include "io/case_file.hpp"
#include "section/clt_section.hpp"

namespace si {
namespace {

// A flat clamped plate, linear kinematics, a 1 mm sphere on a 2 mm mesh: only the apex node is
// ever in contact (its neighbours lie beyond the sphere), so the problem is linear in the depth;
// with the nodal face pressure (the node's multiplier over its area) so is the recovery.
const char* kLinearPlate =
    "material: paper-carbon-epoxy\n"
    "laminate: {layup: \"[0/90]S\", ply_thickness: 0.475 mm}\n"
    "shell: {type: flat_circular_plate, radius: 25 mm, edge: clamped}\n"
    "mesh: {size_apex: 2 mm, size_edge: 4 mm}\n"
    "kinematics: linear\n"
    "indenter: {shape: sphere, radius: 1 mm}\n"
    "path: {depth_max: 1 mm, step: 0.1 mm}\n"
    "damage:\n"
    "  criteria: [max_stress, tsai_wu, hashin, delamination]\n"
    "  face_pressure: nodal\n"
    "  impact_energies: [50 N*mm, 150 N*mm, 1 J]\n"
    "  threshold: {stiffness: olsson}\n";

// The setup stays alive with the result (the onsets' details were read through it).
struct DamageRun {
  std::unique_ptr<IndentationSetup> setup;
  PathResult result;
};

DamageRun run(const std::string& text) {
  DamageRun out;
  out.setup = std::make_unique<IndentationSetup>(parse_case_file(text, "case.yaml"), 1);
  out.result = run_indentation_path(*out.setup);
  return out;
}

// The first depth of the path's points whose force reaches `load` (the end if none does).
double load_reached_before(const PathResult& r, double load) {
  for (const PathPoint& p : r.points)
    if (p.state.force >= load) return p.state.depth;
  return r.points.back().state.depth;
}

double index_of(const PathPoint& p, Criterion c) {
  return p.state.failure[static_cast<int>(c)].index;
}

TEST(DamagePath, LinearIndicesProportionalToDepthAndOnsetAtTheClosedFormRatio) {
  const DamageRun done = run(kLinearPlate);
  const PathResult& r = done.result;
  const IndentationSetup* s = done.setup.get();
  ASSERT_TRUE(r.completed) << r.reason;
  ASSERT_EQ(r.method, RunMethod::kLinearFastPath);
  ASSERT_EQ(r.points.size(), 11u);
  for (std::size_t i = 1; i < r.points.size(); ++i)
    ASSERT_EQ(r.points[i].state.contact_nodes, 1) << "the test needs a fixed contact set";
  const PathPoint& ref = r.points[1];  // h = 0.1 mm
  const double h_ref = ref.state.depth;
  for (Criterion c : {Criterion::kMaxStress, Criterion::kTsaiWu, Criterion::kHashin}) {
    const double ratio = index_of(ref, c) / h_ref;
    ASSERT_GT(ratio, 0.0);
    for (std::size_t i = 2; i < r.points.size(); ++i)
      EXPECT_NEAR(index_of(r.points[i], c) / r.points[i].state.depth, ratio, 1e-12 * ratio)
          << "point " << i;
    // The onset: h_ref / index(h_ref), inside the path (index(0.1 mm) ~ 0.65-0.72).
    const double expected = h_ref / index_of(ref, c);
    int found = 0;
    for (const DamageOnset& o : r.damage.onsets)
      if (o.criterion == c) {
        ++found;
        EXPECT_TRUE(o.located);
        EXPECT_NEAR(o.depth, expected, 1e-10 * (1 + expected));
        EXPECT_NEAR(o.force, ref.state.force * o.depth / h_ref, 1e-9 * o.force);
        EXPECT_EQ(r.events[o.event].name, kDamageOnsetEvent);
        EXPECT_EQ(o.at.node, s->model.apex_node());
      }
    EXPECT_EQ(found, 1) << criterion_name(c);
  }
  // Must not report: at the apex the interlaminar shear vanishes by symmetry and the normal
  // stress is compressive, so the delamination index stays ~0 and never reaches 1.
  EXPECT_LT(index_of(r.points.back(), Criterion::kQuadraticDelamination), 1e-6);
  for (const DamageOnset& o : r.damage.onsets)
    EXPECT_NE(o.criterion, Criterion::kQuadraticDelamination);
}

// The resolved face pressure (damage.face_pressure: hertz, the default): the contacted face's
// sigma33 at the apex is -p0 of Hertz, p0 = (6 F E*^2 / (pi^3 R^2))^(1/3) (Johnson 1985, eq.
// 4.24) with E* and R of the laminate's anisotropic half-space law (k = (4/3) E* R^0.5). On the
// linear plate the maximum-stress onset is that compression reaching Z_C, at
// F = pi^3 R^2 Z_C^3 / (6 E*^2): a force that no mesh size enters.
TEST(DamagePath, HertzFacePressureMaxStressOnsetAtTheClosedForm) {
  std::string text = kLinearPlate;
  text.replace(text.find("  face_pressure: nodal\n"), 22, "");
  const DamageRun done = run(text);
  const PathResult& r = done.result;
  ASSERT_TRUE(r.completed) << r.reason;
  const LocalContactLaw law = face_pressure_law(done.setup->spec);
  ASSERT_EQ(law.kind, LocalLawKind::kPowerLaw);
  const double R = law.radius, E = 3 * law.k / (4 * std::sqrt(R)), Z_C = 200;  // docs/materials.md
  const double pi = std::acos(-1.0);
  const double expected = pi * pi * pi * R * R * Z_C * Z_C * Z_C / (6 * E * E);
  int found = 0;
  for (const DamageOnset& o : r.damage.onsets)
    if (o.criterion == Criterion::kMaxStress) {
      ++found;
      EXPECT_TRUE(o.located);
      EXPECT_EQ(o.at.mode, FailureMode::kNormalCompression);
      EXPECT_EQ(o.at.ply, 3);  // the contacted outer ply's top
      EXPECT_EQ(o.at.position, PlyPosition::kTop);
      EXPECT_NEAR(o.force, expected, 1e-6 * expected);
    }
  EXPECT_EQ(found, 1);
}

TEST(DamagePath, ThresholdIsTheDamageFunctionsValue) {
  const DamageRun done = run(kLinearPlate);
  const PathResult& r = done.result;
  const IndentationSetup* s = done.setup.get();
  ASSERT_TRUE(r.damage.threshold);
  const DelaminationThreshold expected = delamination_threshold(
      d_block(clt_abd(s->spec.laminate)), 0.788, EffectiveBendingStiffness::kOlsson, 1);
  EXPECT_EQ(r.damage.threshold->load, expected.load);
  EXPECT_EQ(r.damage.threshold->D_effective, expected.D_effective);
  // The path's force reaches it between two points, linearly interpolated (linear problem).
  // Force proportional to depth (one node in contact): the depth is load / stiffness.
  ASSERT_LT(load_reached_before(r, expected.load), r.points.back().state.depth);
  const double stiffness = r.points[1].state.force / r.points[1].state.depth;
  EXPECT_NEAR(r.damage.threshold_depth, expected.load / stiffness, 1e-12);
}

TEST(DamagePath, ImpactEnergyDepthSolvesTheTrapezoidalWork) {
  const DamageRun done = run(kLinearPlate);
  const PathResult& r = done.result;
  ASSERT_EQ(r.damage.energies.size(), 3u);
  // The trapezoidal work of (depth, force), independently of the run's work column.
  std::vector<double> work{0.0};
  for (std::size_t i = 1; i < r.points.size(); ++i)
    work.push_back(work.back() + 0.5 * (r.points[i - 1].state.force + r.points[i].state.force) *
                                     (r.points[i].state.depth - r.points[i - 1].state.depth));
  for (const EnergyPoint& e : r.damage.energies) {
    if (e.energy > work.back()) {
      EXPECT_EQ(e.outcome, EnergyOutcome::kBeyondPath);
      EXPECT_TRUE(std::isnan(e.depth));
      continue;
    }
    ASSERT_EQ(e.outcome, EnergyOutcome::kReached);
    std::size_t k = 1;
    while (work[k] < e.energy) ++k;
    // W(h) = W0 + F0 t + k t^2 / 2 on the segment, t = h - h0, k its force slope: solve W = E.
    const IndentationState &a = r.points[k - 1].state, &b = r.points[k].state;
    const double slope = (b.force - a.force) / (b.depth - a.depth);
    const double c = work[k - 1] - e.energy;
    const double t = (-a.force + std::sqrt(a.force * a.force - 2 * slope * c)) / slope;
    EXPECT_NEAR(e.depth, a.depth + t, 1e-12 * (1 + e.depth));
    EXPECT_NEAR(e.force, a.force + slope * t, 1e-9 * e.force);
  }
  EXPECT_EQ(r.damage.energies[2].outcome, EnergyOutcome::kBeyondPath);  // 1 J > the path's work
}

TEST(DamagePath, ContinuationLocatesTheOnsetWhereTheIndexIsOne) {
  const DamageRun done =
      run("material: paper-carbon-epoxy\n"
          "laminate: {layup: \"[0/90]S\", ply_thickness: 0.475 mm}\n"
          "mesh: {size_apex: 2 mm, size_edge: 5 mm}\n"
          "path: {depth_max: 0.6 mm, step: 0.1 mm}\n"
          "damage: {criteria: [hashin, delamination], recovery: refined}\n");
  const PathResult& r = done.result;
  ASSERT_TRUE(r.completed) << r.reason;
  ASSERT_EQ(r.method, RunMethod::kPseudoArclength);
  ASSERT_FALSE(r.damage.onsets.empty());
  const int column = [&] {
    for (std::size_t i = 0; i < r.monitor_names.size(); ++i)
      if (r.monitor_names[i] == "hashin_index") return static_cast<int>(i);
    return -1;
  }();
  ASSERT_GE(column, 0);
  int hashin = 0;
  for (const DamageOnset& o : r.damage.onsets) {
    const cont::Event& e = r.events[o.event];
    EXPECT_TRUE(o.located);
    // Bracketed by the points around it.
    EXPECT_LT(index_of(r.points[e.step - 1], o.criterion), 1.0);
    EXPECT_GE(index_of(r.points[e.step], o.criterion), 1.0);
    if (o.criterion != Criterion::kHashin) continue;
    ++hashin;
    EXPECT_NEAR(e.monitors[column], 1.0, 1e-6);  // the index at the located point
    EXPECT_NE(o.at.mode, FailureMode::kNone);
    // The event's work gives back its depth through the impact-energy interpolation.
    ForceDepthPath path;
    for (const PathPoint& p : r.points) {
      path.depth.push_back(p.state.depth);
      path.force.push_back(p.state.force);
    }
    const EnergyPoint back = depth_at_energy(path, o.work, WorkInterpolation::kTrapezoid);
    EXPECT_NEAR(back.depth, o.depth, 1e-9);
  }
  EXPECT_EQ(hashin, 1);
}

TEST(DamagePath, RunWithoutDamageHasTheBaseColumnsOnly) {
  std::string text = kLinearPlate;
  text = text.substr(0, text.find("damage:"));
  const DamageRun done = run(text);
  const PathResult& r = done.result;
  const IndentationSetup* s = done.setup.get();
  EXPECT_TRUE(r.criteria.empty());
  EXPECT_EQ(run_columns(r.criteria), base_columns());
  EXPECT_FALSE(s->damage);
  EXPECT_TRUE(std::isnan(index_of(r.points.back(), Criterion::kHashin)));
  EXPECT_TRUE(r.damage.onsets.empty());
}

}  // namespace
}  // namespace si
