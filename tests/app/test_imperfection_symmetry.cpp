// `path.imperfection` on a quarter model (mesh.symmetry: quarter): the seeded mode respects the
// symmetry planes, and so must the imperfect mesh's directors. They did not: the directors of the
// plane nodes turned with the one-sided element normals, and the run was refused with "support 1:
// the director of node 0 ... is not in the symmetry plane", naming the key `indenter` (seen on
// the paper's cap, [0/0]2S, with linear and with nonlinear kinematics).
// model/geometric_imperfection.hpp keep_directors_in_symmetry_planes mends it; the unit test is
// GeometricImperfection.SymmetryPlaneDirectorsStayInTheirPlanes.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_support.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;
using testing::contains;
using testing::fresh_dir;
using testing::read_file;
using testing::run_cli;
using testing::write_case;

std::string quarter_cap(const std::string& kinematics) {
  return "material: paper-carbon-epoxy\n"
         "laminate: {layup: \"[0/0]2S\", ply_thickness: 0.475 mm}\n"
         "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: clamped}\n"
         "mesh: {size_apex: 1.5 mm, size_edge: 4 mm, refine_radius: 8 mm, symmetry: quarter}\n"
         "kinematics: " +
         kinematics +
         "\n"
         "path: {depth_max: 1 mm, step: 0.1 mm, stability: true,\n"
         "       imperfection: {mode: 1, amplitude: 0.1 mm}}\n"
         "output: {vtu_every: 0}\n";
}

// Both kinematics: the mode comes from the last point of the perfect path (this cap has no
// stability change to 1 mm), the imperfect path then runs to depth_max, and path.json records the
// imperfection.
TEST(ImperfectionSymmetry, QuarterCapWithAnImperfectionRuns) {
  for (const std::string kinematics : {"nonlinear", "linear"}) {
    const fs::path dir = fresh_dir("imperfection_quarter_" + kinematics);
    const fs::path c = write_case(dir, quarter_cap(kinematics));
    const auto r = run_cli("run '" + c.string() + "' --out '" + (dir / "out").string() + "'");
    ASSERT_EQ(r.exit_code, 0) << kinematics << ": " << r.output;
    EXPECT_FALSE(contains(r.output, "symmetry plane")) << r.output;
    const auto path = nlohmann::json::parse(read_file(dir / "out" / "path.json"));
    ASSERT_TRUE(path.contains("imperfection")) << path.dump(1).substr(0, 500);
    const std::string status = path.at("status").get<std::string>();
    EXPECT_TRUE(status == "completed" || status == "reached_bound") << kinematics << ": " << status;
  }
}

}  // namespace
}  // namespace si
