// The hinged cylindrical roof of Sze, Liu & Lo (2004) sec. 3.8(a) (R = 2540 mm, length 508 mm,
// 0.2 rad, h = 12.7 mm, E = 3102.75 MPa, nu = 0.3, straight edges hinged, curved ends free)
// pressed at its centre, full model (16 x 16 mitc4). Its snap-through path carries two asymmetric
// bifurcations on its unstable part, which a quarter model cannot see. Three checks of
// path.stability and path.imperfection (issue 15 items 1 and 2) on a shell:
// 1. Depth control equals load control. A flat punch on the mid-surface is a dead point load along
//    z on the apex node, and an antisymmetric mode leaves the apex's deflection unchanged, so the
//    tangent restricted to the contact and the load-controlled tangent vanish together: `run` and
//    `static` with the point load locate the same two bifurcations, depth (= apex deflection) and
//    force, to 1e-6 (each is located to 1e-8 in arclength), and the same force maximum. Both are
//    bifurcations under load control too (the load factor keeps falling through them): with
//    these steps the former classification, by |dp/ds| at the located point, called the second a
//    limit point.
// 2. path.imperfection seeded from the first one's mode: the mode is antisymmetric about one of
//    the roof's mid-planes, and the imperfect path has no bifurcation left: it is stable
//    throughout (what must not be reported: any stability change).
// 3. The response to an antisymmetric imperfection is even in its amplitude (the roof's mirror
//    image has the imperfection's other sign): the force maximum moves by O(a^2), so 0.5 mm and
//    0.1 mm move it in the ratio 25 (within 10 %: the next term is O(a^4)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/indentation_run.hpp"
#include "cli_test_support.hpp"
#include "io/case_file.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::fresh_dir;
using testing::read_file;
using testing::run_cli;

const std::string kRoof =
    "material: {type: isotropic, E: 3102.75 MPa, nu: 0.3}\n"
    "laminate: {layup: \"[0]\", ply_thickness: 12.7 mm}\n"
    "shell: {type: cylindrical_panel, radius: 2540 mm, length: 508 mm, angle: 11.459156 deg,"
    " edge: free}\n"
    "mesh: {size_apex: 31.8 mm, symmetry: full}\n"
    "supports: [{on: straight_edges, type: hinged}]\n"
    "output: {formats: [json], vtu_every: 0}\n";

// The depth-controlled roof: a flat punch on the mid-surface, to 25 mm (past both bifurcations
// and the force minimum), with `path_extra` inside path: {...}.
std::string pressed_roof(const std::string& path_extra) {
  return kRoof +
         "indenter: {shape: flat_punch, radius: 5 mm}\n"
         "contact: {surface: mid}\n"
         "path: {depth_max: 25 mm, step: 1 mm, step_max: 2 mm, stability: true" +
         path_extra + "}\n";
}

struct Change {
  double depth, force;
  std::string criticality;
};

std::vector<Change> changes_of(const json& events, const char* depth_key) {
  std::vector<Change> out;
  for (const json& e : events)
    if (e["type"] == "stability_change")
      out.push_back({e[depth_key].get<double>(), e["force_N"].get<double>(),
                     e.value("criticality", std::string())});
  return out;
}

// The located force maximum (event monitor_max of force_N) of a run's path.json.
double force_maximum(const json& path) {
  for (const json& e : path["events"])
    if (e["type"] == "monitor_max") return e["force_N"].get<double>();
  return std::nan("");
}

json run_case(const fs::path& dir, const std::string& name, const std::string& yaml,
              const std::string& command = "run") {
  const fs::path file = dir / (name + ".yaml");
  std::ofstream(file) << yaml;
  const auto r =
      run_cli(command + " '" + file.string() + "' --out '" + (dir / name).string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return json::parse(read_file(dir / name / (command == "run" ? "path.json" : "static.json")));
}

TEST(RoofBifurcation, DepthControlLocatesTheLoadControlledBifurcations_SzeLiuLo2004Sec38a) {
  const fs::path dir = fresh_dir("roof_bifurcation");
  const json pressed = run_case(dir, "pressed", pressed_roof(""));
  const json loaded =
      run_case(dir, "loaded",
               kRoof +
                   "loads: [{type: point, on: apex, force: [0 N, 0 N, -3000 N]}]\n"
                   "static: {method: pseudo_arclength, step: 0.2 mm, step_max: 0.25 mm,"
                   " parameter_weight: 10 mm, load_factor_max: 1.1, stability: true}\n",
               "static");
  const std::vector<Change> depth = changes_of(pressed["events"], "depth_mm");
  std::vector<Change> load;
  for (const Change& c : changes_of(loaded["events"], "apex_deflection_mm"))
    if (c.criticality == "bifurcation") load.push_back(c);  // load control: also the two folds
  ASSERT_EQ(depth.size(), 2u);
  ASSERT_EQ(load.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(depth[i].criticality, "bifurcation");
    EXPECT_NEAR(depth[i].depth, load[i].depth, 1e-6 * load[i].depth) << i;
    EXPECT_NEAR(depth[i].force, load[i].force, 1e-6 * load[i].force) << i;
  }
  double load_max = 0;
  for (const json& e : loaded["events"])
    if (e["type"] == "limit_point") load_max = std::max(load_max, e["force_N"].get<double>());
  EXPECT_NEAR(force_maximum(pressed), load_max, 1e-6 * load_max);
  EXPECT_NEAR(load_max / 3000, 0.7421, 0.01);  // Sze et al.'s S4R limit load, 24 x 24 quarter
}

// The seeded mode's translations are odd about one of the roof's two mid-planes.
double antisymmetry_defect(const Mesh& reference, const Eigen::MatrixXd& shape) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : reference.nodes) centre += p;
  centre /= reference.num_nodes();
  double best = 1e300;
  for (int axis : {0, 1}) {
    double defect = 0;
    for (int i = 0; i < reference.num_nodes(); ++i) {
      Eigen::Vector3d mirror = reference.nodes[i];
      mirror[axis] = 2 * centre[axis] - mirror[axis];
      int j = 0;
      for (int k = 1; k < reference.num_nodes(); ++k)
        if ((reference.nodes[k] - mirror).norm() < (reference.nodes[j] - mirror).norm()) j = k;
      defect = std::max(defect, std::abs(shape(i, 2) + shape(j, 2)));  // w odd under the mirror
    }
    best = std::min(best, defect);
  }
  return best / shape.col(2).cwiseAbs().maxCoeff();
}

TEST(RoofBifurcation, ImperfectionFromTheCriticalModeRemovesTheBifurcations) {
  const fs::path dir = fresh_dir("roof_imperfection");
  const json perfect = run_case(dir, "perfect", pressed_roof(""));
  ASSERT_EQ(changes_of(perfect["events"], "depth_mm").size(), 2u);
  double moved[2] = {0, 0};
  const double amplitudes[2] = {0.1, 0.5};
  for (int k = 0; k < 2; ++k) {
    const std::string a = std::to_string(amplitudes[k]);
    const json imperfect =
        run_case(dir, "imperfect_" + std::to_string(k),
                 pressed_roof(", imperfection: {mode: 1, amplitude: " + a + " mm}"));
    const json& seed = imperfect["imperfection"];
    EXPECT_EQ(seed["taken_at"], "stability_change");
    EXPECT_EQ(seed["criticality"], "bifurcation");
    EXPECT_NEAR(seed["depth_mm"].get<double>(), changes_of(perfect["events"], "depth_mm")[0].depth,
                1e-9);
    EXPECT_TRUE(changes_of(imperfect["events"], "depth_mm").empty()) << imperfect["events"];
    for (const json& p : imperfect["points"]) EXPECT_EQ(p["stable"].get<double>(), 1.0);
    moved[k] = force_maximum(perfect) - force_maximum(imperfect);
  }
  EXPECT_GT(moved[0], 0.0);  // the imperfection lowers the peak
  EXPECT_NEAR(moved[1] / moved[0], 25.0, 2.5);

  // The seed itself: the mode's translations, antisymmetric, the largest = the amplitude.
  const IndentationSetup s(
      parse_case_file(pressed_roof(", imperfection: {mode: 1, amplitude: 0.1 mm}"), "roof"), 1);
  ASSERT_TRUE(s.imperfection);
  const Eigen::MatrixXd& shape = s.imperfection->shape;
  EXPECT_NEAR(shape.cwiseAbs().maxCoeff(), 0.1, 1e-15);
  Eigen::Index row = 0, col = 0;
  shape.cwiseAbs().maxCoeff(&row, &col);
  EXPECT_GT(shape(row, col), 0.0);  // the sign convention: the largest component positive
  Mesh reference = s.model.mesh;
  for (int i = 0; i < reference.num_nodes(); ++i) reference.nodes[i] -= shape.row(i).transpose();
  // Odd to 1e-4 of its largest translation (measured 1.0e-4): the event point lies within the
  // location tolerance of a singular tangent, where the corrector's round-off is amplified along
  // the critical mode, so the state's symmetry holds to that only; a symmetric mode would have a
  // defect of 2.
  EXPECT_LT(antisymmetry_defect(reference, shape), 1e-3);
}

// path.branch_switch at the first bifurcation: the new (asymmetric) branch leaves the fundamental
// path at B1 and arrives at B2, where it turns back in depth (a pitchfork seen from the new branch:
// the depth's fold is exactly B2 by the roof's symmetry, and the run stops there). Its points are
// stable (the depth-controlled roof follows it), lie between B1 and B2, carry branch 1 and differ
// from the fundamental path's at the same depth; direction -1 (the mirror image) gives the same
// forces. What must not happen: a point of the fundamental branch past B1 in the output, or the
// branch followed round its loop again.
TEST(RoofBifurcation, BranchSwitchingFollowsTheAsymmetricBranchFromOneBifurcationToTheOther) {
  const fs::path dir = fresh_dir("roof_branch_switch");
  const json perfect = run_case(dir, "perfect", pressed_roof(""));
  const std::vector<Change> b = changes_of(perfect["events"], "depth_mm");
  ASSERT_EQ(b.size(), 2u);
  double fold_force[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const int direction = k == 0 ? 1 : -1;
    const json run =
        run_case(dir, "switched_" + std::to_string(k),
                 pressed_roof(", branch_switch: {direction: " + std::to_string(direction) + "}"));
    EXPECT_EQ(run["status"], "completed") << run["reason"];
    int switched = 0;
    for (const json& p : run["points"]) {
      const double h = p["depth_mm"].get<double>();
      if (p["branch"].get<double>() == 0) {
        EXPECT_LT(h, b[0].depth);  // nothing of the fundamental branch past B1
        EXPECT_EQ(switched, 0);    // and nothing of it after the switch
        continue;
      }
      ++switched;
      EXPECT_GT(h, b[0].depth);
      EXPECT_LT(h, b[1].depth);
      EXPECT_EQ(p["stable"].get<double>(), 1.0) << h;
    }
    EXPECT_GE(switched, 3);
    std::vector<const json*> folds;
    for (const json& e : run["events"])
      if (e["type"] == "limit_point") folds.push_back(&e);
    ASSERT_EQ(folds.size(), 1u);
    EXPECT_NEAR((*folds[0])["depth_mm"].get<double>(), b[1].depth, 1e-6 * b[1].depth);
    fold_force[k] = (*folds[0])["force_N"].get<double>();
    EXPECT_NEAR(fold_force[k], b[1].force, 1e-6 * b[1].force);
  }
  EXPECT_NEAR(fold_force[0], fold_force[1], 1e-6 * fold_force[0]);
}

}  // namespace
}  // namespace si
