// Issue 16: the damage onset on the source paper's cap converges with the mesh. The cap
// ([0/90]2S, clamped, base radius 25 mm, R = 80.9 mm, 8 plies of 0.475 mm of paper-carbon-epoxy,
// 12.7 mm sphere, nonlinear, full model) is run with the four criteria monitored on three meshes
// refined by sqrt(2) everywhere (apex and edge sizes 1.41/2.83, 1/2, 0.71/1.41 mm).
//
// With the nodal face pressure (a node's multiplier over its tributary area) and patches of the
// 25 nearest nodes the onsets did not converge: the maximum-stress onset sat at F = Z_C
// size_apex^2 and halved with each refinement (docs/theory/failure.md 7). The recovery now reads
// Hertz's pressure of the indenter's force (the laminate's anisotropic half-space sizing the
// contact radius) and fits the strains over twice the thickness around each node. Checked here:
//  * the maximum-stress onset is the contacted face's compression at Hertz's closed form
//    F = pi^3 R^2 Z_C^3 / (6 E*^2) on every mesh (no mesh size enters it);
//  * the Tsai-Wu, Hashin and delamination onset forces of the three meshes lie within 2 % of the
//    finest mesh's (the tolerance stated in docs/theory/failure.md 7; measured 0.1, 0.1 and
//    0.8 %). Their differences are at that level and change sign, so no Richardson limit is
//    formed (with a patch of one thickness the delamination onset did not converge: 3141, 2983,
//    2731 N).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "analysis/indentation_run.hpp"
#include "analysis/local_contact.hpp"
#include "io/case_file.hpp"

namespace si {
namespace {

struct MeshRun {
  double size_apex = 0;
  int unknowns = 0;
  std::map<Criterion, DamageOnset> onsets;  // the first of each criterion
  LocalContactLaw face_law;                 // what sized the face pressure
};

MeshRun run_mesh(double size_apex) {
  const std::string text =
      "material: paper-carbon-epoxy\n"
      "laminate: {layup: \"[0/90]2S\", ply_thickness: 0.475 mm, reference: mid}\n"
      "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n"
      "mesh: {size_apex: " +
      std::to_string(size_apex) + " mm, size_edge: " + std::to_string(2 * size_apex) +
      " mm, refine_radius: 13 mm, symmetry: full}\n"
      "kinematics: nonlinear\n"
      "indenter: {shape: sphere, radius: 12.7 mm}\n"
      "path: {method: pseudo_arclength, depth_max: 0.4 mm, step: 0.05 mm}\n"
      "damage: {criteria: [max_stress, tsai_wu, hashin, delamination]}\n";
  IndentationSetup setup(parse_case_file(text, "case.yaml"), 1);
  const PathResult r = run_indentation_path(setup);
  EXPECT_TRUE(r.completed) << r.reason;
  MeshRun out;
  out.size_apex = size_apex;
  out.unknowns = setup.problem->num_shell_unknowns();
  out.face_law = face_pressure_law(setup.spec);
  for (const DamageOnset& o : r.damage.onsets) out.onsets.emplace(o.criterion, o);
  return out;
}

TEST(DamageOnsetConvergence, PaperCapOnsetsConvergeWithTheResolvedFacePressure) {
  const double Z_C = 200;  // MPa, paper-carbon-epoxy (docs/materials.md)
  const double pi = std::acos(-1.0);
  std::printf("apex/edge (mm) | unknowns | criterion | depth (mm) | force (N) | mode, where\n");
  std::vector<MeshRun> runs;
  for (double size : {std::sqrt(2.0), 1.0, 1.0 / std::sqrt(2.0)}) {
    runs.push_back(run_mesh(size));
    const MeshRun& m = runs.back();
    for (const auto& [criterion, o] : m.onsets)
      std::printf("%.3f/%.3f | %d | %s | %.4f | %.1f | mode %d, ply %d%s\n", size, 2 * size,
                  m.unknowns, criterion_name(criterion), o.depth, o.force,
                  static_cast<int>(o.at.mode), o.at.ply + 1, o.at.interface ? " interface" : "");
    ASSERT_TRUE(m.onsets.count(Criterion::kMaxStress)) << size << " mm mesh";
    const DamageOnset& o = m.onsets.at(Criterion::kMaxStress);
    EXPECT_TRUE(o.located);
    EXPECT_EQ(o.at.mode, FailureMode::kNormalCompression);
    EXPECT_EQ(o.at.ply, 7);
    EXPECT_EQ(o.at.position, PlyPosition::kTop);
    const double R = m.face_law.radius, E = 3 * m.face_law.k / (4 * std::sqrt(R));
    const double hertz = pi * pi * pi * R * R * Z_C * Z_C * Z_C / (6 * E * E);
    EXPECT_NEAR(o.force, hertz, 1e-6 * hertz) << size << " mm mesh";
  }
  for (Criterion c : {Criterion::kTsaiWu, Criterion::kHashin, Criterion::kQuadraticDelamination}) {
    std::vector<double> f;
    for (const MeshRun& m : runs) {
      ASSERT_TRUE(m.onsets.count(c))
          << criterion_name(c) << " on the " << m.size_apex << " mm mesh";
      f.push_back(m.onsets.at(c).force);
    }
    double spread = 0;
    for (double v : f) spread = std::max(spread, std::abs(v - f.back()) / f.back());
    std::printf("%s: largest difference from the finest mesh %.2f %%\n", criterion_name(c),
                100 * spread);
    EXPECT_LT(spread, 0.02) << criterion_name(c);
  }
}

}  // namespace
}  // namespace si
