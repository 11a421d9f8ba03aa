// build_shell_model: the mesh of each shell type with its "apex" and "edge" sets, the mapping of
// sizes to element counts, supports and symmetry planes, loads, and the refusals.
#include "model/shell_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "io/case_file.hpp"
#include "model/supports.hpp"

namespace si {
namespace {

const std::string kHead =
    "material: steel\n"
    "laminate: {layup: \"[0]\", ply_thickness: 1 mm}\n";

ShellModel build(const std::string& body) {
  return build_shell_model(parse_case_file(kHead + body, "model.yaml"));
}

void expect_apex_at_origin_in_plan(const ShellModel& m) {
  const Vector3d& apex = m.mesh.nodes[m.apex_node()];
  EXPECT_NEAR(apex.x(), 0.0, 1e-12);
  EXPECT_NEAR(apex.y(), 0.0, 1e-12);
  EXPECT_FALSE(m.mesh.node_sets.at("edge").empty());
}

TEST(ShellModel, PaperCapDefaultsFullClampedMitc4) {
  const ShellModel m = build("load: {type: apex_force, force: 2 kN}\n");
  expect_apex_at_origin_in_plan(m);
  EXPECT_EQ(m.element->name(), "mitc4");
  EXPECT_EQ(m.kinematics, Kinematics::kNonlinear);
  EXPECT_DOUBLE_EQ(m.symmetry_factor, 1.0);
  ASSERT_EQ(m.supports.size(), 1u);
  EXPECT_EQ(m.supports[0].kind, SupportKind::kClamped);
  ASSERT_EQ(m.loads.points.size(), 1u);
  EXPECT_EQ(m.loads.points[0].node_set, "apex");
  EXPECT_DOUBLE_EQ(m.loads.points[0].force.z(), -2000.0);
  EXPECT_TRUE(m.warnings.empty());
  // The law is the VAM section of 1 mm of steel: A11 = E t / (1 - nu^2).
  EXPECT_NEAR(m.law.A_R(0, 0), 210000.0 / (1 - 0.09), 1e-6 * 210000.0);
}

TEST(ShellModel, QuarterModelHasSymmetryPlanesAndAQuarterOfTheForce) {
  const ShellModel m = build(
      "mesh: {symmetry: quarter}\nload: {type: apex_force, force: 2 kN}\nshell: {type: "
      "flat_circular_plate, radius: 20 mm, edge: hinged}\n");
  expect_apex_at_origin_in_plan(m);
  EXPECT_DOUBLE_EQ(m.symmetry_factor, 4.0);
  ASSERT_EQ(m.supports.size(), 3u);
  EXPECT_EQ(m.supports[0].kind, SupportKind::kHinged);
  EXPECT_EQ(m.supports[1].kind, SupportKind::kSymmetryPlane);
  EXPECT_EQ(m.supports[1].plane_axis, 0);
  EXPECT_EQ(m.supports[2].plane_axis, 1);
  EXPECT_DOUBLE_EQ(m.loads.points[0].force.z(), -500.0);
  EXPECT_NO_THROW(make_dof_map(m.mesh, m.supports));
}

TEST(ShellModel, RectangularPlateSizesMapToEvenElementCounts) {
  // 30 x 20 mm with elements of at most 4 mm: ceil(30 / 4) = 8 and ceil(20 / 4) = 5 -> 6.
  const ShellModel full = build(
      "shell: {type: rectangular_plate, length_x: 30 mm, length_y: 20 mm, edge: "
      "simply_supported}\nmesh: {size_apex: 4 mm}\n");
  EXPECT_EQ(full.mesh.num_elements(), 8 * 6);
  expect_apex_at_origin_in_plan(full);
  EXPECT_NO_THROW(make_dof_map(full.mesh, full.supports));
  const ShellModel quarter = build(
      "shell: {type: rectangular_plate, length_x: 30 mm, length_y: 20 mm}\n"
      "mesh: {size_apex: 4 mm, symmetry: quarter}\n");
  EXPECT_EQ(quarter.mesh.num_elements(), 4 * 3);
  expect_apex_at_origin_in_plan(quarter);
  for (int n : quarter.mesh.node_sets.at("edge")) {
    const Vector3d& x = quarter.mesh.nodes[n];
    EXPECT_TRUE(std::abs(x.x() - 15) < 1e-12 || std::abs(x.y() - 10) < 1e-12);
  }
}

TEST(ShellModel, CylindricalPanelCrownCentreIsTheApex) {
  // Arc 50 mm * 60 deg = 52.4 mm and length 40 mm with 5 mm elements: 12 x 8.
  const ShellModel m = build(
      "shell: {type: cylindrical_panel, radius: 50 mm, length: 40 mm, angle: 60 deg}\n"
      "mesh: {size_apex: 5 mm}\nload: {type: pressure, pressure: 0.1 MPa, follower: true}\n");
  EXPECT_EQ(m.mesh.num_elements(), 12 * 8);
  expect_apex_at_origin_in_plan(m);
  EXPECT_NEAR(m.mesh.nodes[m.apex_node()].z(), 50.0, 1e-12);
  ASSERT_EQ(m.loads.pressures.size(), 1u);
  EXPECT_DOUBLE_EQ(m.loads.pressures[0].pressure, -0.1);  // against the director
  EXPECT_TRUE(m.loads.pressures[0].follower);
  const ShellModel q = build(
      "shell: {type: cylindrical_panel, radius: 50 mm, length: 40 mm, angle: 60 deg}\n"
      "mesh: {size_apex: 5 mm, symmetry: quarter}\n");
  EXPECT_EQ(q.mesh.num_elements(), 6 * 4);
  EXPECT_NO_THROW(make_dof_map(q.mesh, q.supports));
}

TEST(ShellModel, QuarterModelOfAnAnglePlyIsRefusedNamingMeshSymmetry) {
  try {
    build_shell_model(
        parse_case_file("material: paper-carbon-epoxy\n"
                        "laminate: {layup: \"[45/-45]2S\", ply_thickness: 0.475 mm}\n"
                        "mesh: {symmetry: quarter}\n",
                        "angle.yaml"));
    FAIL() << "accepted a quarter model of [45/-45]2S";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().file, "angle.yaml");
    EXPECT_EQ(e.where().key, "mesh.symmetry");
    EXPECT_EQ(e.where().value, "quarter");
    EXPECT_NE(e.reason().find("bending-twisting"), std::string::npos) << e.reason();
  }
  // [0/90]2S is specially orthotropic: accepted.
  EXPECT_NO_THROW(build_shell_model(
      parse_case_file("material: paper-carbon-epoxy\n"
                      "laminate: {layup: \"[0/90]2S\", ply_thickness: 0.475 mm}\n"
                      "mesh: {size_apex: 2 mm, size_edge: 4 mm, symmetry: quarter}\n",
                      "cross.yaml")));
}

TEST(ShellModel, SimplySupportedCapIsRefused) {
  try {
    build(
        "shell: {type: spherical_cap, base_radius: 25 mm, radius: 80.9 mm, edge: "
        "simply_supported}\n");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().key, "shell.edge");
  }
}

TEST(ShellModel, Bernstein4CarriesAPatchTestWarning) {
  const ShellModel m = build("mesh: {element: bernstein4, size_apex: 2 mm, size_edge: 4 mm}\n");
  EXPECT_EQ(m.element->name(), "bernstein4");
  ASSERT_EQ(m.warnings.size(), 1u);
  EXPECT_NE(m.warnings[0].find("patch test"), std::string::npos);
}

void expect_refused(const std::string& body, const std::string& key) {
  try {
    build(body);
    ADD_FAILURE() << "accepted:\n" << body;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput) << e.what();
    EXPECT_EQ(e.where().file, "model.yaml") << e.what();
    EXPECT_EQ(e.where().key, key) << e.what();
  }
}

TEST(ShellModel, MeshGeneratorErrorsNameTheCaseKey) {
  expect_refused("mesh: {size_apex: 3 mm, size_edge: 1 mm}\n", "mesh.size_apex");
  expect_refused("shell: {type: spherical_cap, base_radius: 80.9 mm, radius: 80.9 mm}\n",
                 "shell.base_radius");
}

TEST(ShellModel, AbsurdMeshSizeIsRefusedBeforeMeshing) {
  // 1e-6 mm over a 25 mm cap would be ~1e15 elements: refused, not attempted.
  expect_refused("mesh: {size_apex: 0.000001 mm}\n", "mesh.size_apex");
}

TEST(ShellModel, EveryElementChoiceReachesTheModel) {
  for (const char* name : {"mitc4", "mitc4-plain", "bernstein4"}) {
    const ShellModel m = build(std::string("mesh: {element: ") + name +
                               ", size_apex: 2 mm, size_edge: 4 mm, symmetry: quarter}\n");
    EXPECT_EQ(m.element->name(), name);
  }
}

}  // namespace
}  // namespace si
