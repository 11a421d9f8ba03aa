#include "io/case_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io/material_reader.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

std::vector<double> angles_of(const Laminate& laminate) {
  std::vector<double> angles;
  for (const auto& p : laminate.plies) angles.push_back(p.angle_deg);
  return angles;
}

const char* const kMinimal = R"(
material: paper-carbon-epoxy
laminate: {layup: "[45/-45]2S", ply_thickness: 0.475 mm}
)";

TEST(CaseFile, ReadsThePaperCapStudy) {
  const std::string path = std::string(SHELLINDENT_SOURCE_DIR) + "/studies/paper_cap.yaml";
  const CaseFile c = read_case_file(path);
  EXPECT_EQ(c.file, path);
  EXPECT_EQ(angles_of(c.laminate), (std::vector<double>{0, 90, 0, 90, 90, 0, 90, 0}));
  EXPECT_NEAR(c.laminate.thickness(), 8 * 0.475, 1e-12);
  EXPECT_EQ(c.laminate.reference_offset, 0.0);
  EXPECT_EQ(c.material.name(), "paper-carbon-epoxy");
  EXPECT_EQ(c.laminate.plies[0].material.name(), "paper-carbon-epoxy");
  EXPECT_EQ(c.shell.type, ShellType::kSphericalCap);
  EXPECT_DOUBLE_EQ(c.shell.base_radius, 25.0);
  EXPECT_DOUBLE_EQ(c.shell.radius, 80.9);
  EXPECT_EQ(c.shell.edge, EdgeCondition::kClamped);
  EXPECT_EQ(c.mesh.element, ElementType::kMitc4);
  EXPECT_DOUBLE_EQ(c.mesh.size_apex, 0.5);
  EXPECT_DOUBLE_EQ(c.mesh.size_edge, 2.0);
  EXPECT_EQ(c.mesh.refine_radius, 13.0);
  EXPECT_EQ(c.mesh.symmetry, Symmetry::kFull);
  EXPECT_EQ(c.kinematics, Kinematics::kNonlinear);
  EXPECT_EQ(c.indenter.shape, IndenterShape::kSphere);
  EXPECT_DOUBLE_EQ(c.indenter.radius, 12.7);
  EXPECT_FALSE(c.indenter.material.has_value());
  EXPECT_EQ(c.contact.surface, ContactSurface::kOuter);
  EXPECT_EQ(c.contact.solver, ContactSolver::kKinsol);
  EXPECT_EQ(c.contact.local, LocalContactModel::kNone);
  EXPECT_EQ(c.contact.traction, ContactTraction::kNodal);
  EXPECT_FALSE(c.contact.fbar);
  EXPECT_EQ(c.path.method, PathMethod::kPseudoArclength);
  EXPECT_DOUBLE_EQ(c.path.depth_max, 10.0);
  EXPECT_DOUBLE_EQ(c.path.step, 0.1);
  EXPECT_EQ(c.output.dir, "results/paper_cap_0_90_2s/");
  EXPECT_EQ(c.output.vtu_every, 10);
}

TEST(CaseFile, OptionalSectionsDefaultToThePaperCase) {
  const CaseFile c = parse_case_file(kMinimal, "minimal.yaml");
  EXPECT_EQ(c.file, "minimal.yaml");
  EXPECT_EQ(angles_of(c.laminate), (std::vector<double>{45, -45, 45, -45, -45, 45, -45, 45}));
  EXPECT_EQ(c.shell.type, ShellType::kSphericalCap);
  EXPECT_DOUBLE_EQ(c.shell.base_radius, 25.0);
  EXPECT_DOUBLE_EQ(c.shell.radius, 80.9);
  EXPECT_EQ(c.shell.edge, EdgeCondition::kClamped);
  EXPECT_EQ(c.mesh.element, ElementType::kMitc4);
  EXPECT_FALSE(c.mesh.refine_radius);  // sized from the indenter by the set-up
  EXPECT_EQ(c.kinematics, Kinematics::kNonlinear);
  EXPECT_EQ(c.indenter.shape, IndenterShape::kSphere);
  EXPECT_DOUBLE_EQ(c.indenter.radius, 12.7);
  EXPECT_EQ(c.contact.surface, ContactSurface::kOuter);
  EXPECT_EQ(c.contact.solver, ContactSolver::kKinsol);
  EXPECT_EQ(c.path.method, PathMethod::kPseudoArclength);
  EXPECT_DOUBLE_EQ(c.path.depth_max, 10.0);
  EXPECT_DOUBLE_EQ(c.path.step, 0.1);
  EXPECT_DOUBLE_EQ(c.path.step_min, 1e-4);
  EXPECT_DOUBLE_EQ(c.path.step_max, 1.0);
  EXPECT_TRUE(c.path.depths.empty());
  EXPECT_EQ(c.output.dir, "results/");
  EXPECT_EQ(c.output.vtu_every, 10);
  EXPECT_EQ(c.output.formats, (std::vector<OutputFormat>{OutputFormat::kCsv, OutputFormat::kJson,
                                                         OutputFormat::kVtu}));
}

TEST(CaseFile, AnisotropicLocalLawAndItsChoices) {
  const CaseFile defaults =
      parse_case_file(std::string(kMinimal) + "contact: {local: anisotropic}\n", "a.yaml");
  EXPECT_EQ(defaults.contact.local, LocalContactModel::kAnisotropic);
  EXPECT_EQ(defaults.contact.local_support, LocalSupport::kHalfSpace);
  EXPECT_EQ(defaults.contact.local_plies, LocalPlies::kHomogenised);
  const CaseFile c = parse_case_file(
      std::string(kMinimal) +
          "contact: {local: anisotropic, local_support: plate, local_plies: resolved}\n",
      "b.yaml");
  EXPECT_EQ(c.contact.local_support, LocalSupport::kPlate);
  EXPECT_EQ(c.contact.local_plies, LocalPlies::kResolved);
  for (const auto& [name, support] : {std::pair{"bonded", LocalSupport::kBondedBase},
                                      std::pair{"frictionless", LocalSupport::kFrictionlessBase}})
    EXPECT_EQ(parse_case_file(std::string(kMinimal) +
                                  "contact: {local: anisotropic, local_support: " + name + "}\n",
                              "c.yaml")
                  .contact.local_support,
              support);
}

TEST(CaseFile, ConvertsUnitsToInternalUnits) {
  const CaseFile c = parse_case_file(R"(
material: {type: orthotropic, E1: 18.855 Msi, E2: 10 GPa, E3: 10000 MPa, G12: 6e9 Pa,
           G13: 3 GPa, G23: 6 GPa, nu12: 0.3, nu13: 0.5, nu23: 0.3}
laminate: {layup: "[0/90]S", ply_thickness: 0.0187 in}
shell: {type: spherical_cap, base_radius: 2.5 cm, radius: 0.0809 m}
indenter: {shape: sphere, radius: 0.5 in}
path: {depth_max: 0.01 m, step: 100 um}
)",
                                     "units.yaml");
  EXPECT_NEAR(c.material.constants().E1, 18.855 * 6894.757293168361, 1e-6);
  EXPECT_DOUBLE_EQ(c.material.constants().E3, 10000.0);
  EXPECT_DOUBLE_EQ(c.material.constants().G12, 6000.0);
  EXPECT_DOUBLE_EQ(c.laminate.plies[0].thickness, 0.0187 * 25.4);
  EXPECT_DOUBLE_EQ(c.shell.base_radius, 25.0);
  EXPECT_DOUBLE_EQ(c.shell.radius, 80.9);
  EXPECT_DOUBLE_EQ(c.indenter.radius, 12.7);
  EXPECT_DOUBLE_EQ(c.path.depth_max, 10.0);
  EXPECT_DOUBLE_EQ(c.path.step, 0.1);
}

TEST(CaseFile, InlineMaterials) {
  const CaseFile c = parse_case_file(R"(
material: {type: isotropic, E: 70 GPa, nu: 0.3, name: alu}
laminate: {layup: "[0]", ply_thickness: 2 mm}
)",
                                     "iso.yaml");
  EXPECT_EQ(c.material.name(), "alu");
  EXPECT_TRUE(c.material.is_isotropic());
  EXPECT_DOUBLE_EQ(c.material.constants().E2, 70000.0);
  EXPECT_DOUBLE_EQ(c.material.constants().G12, 70000.0 / 2.6);

  const CaseFile unnamed = parse_case_file(R"(
material: {type: isotropic, E: 70 GPa, nu: 0.3}
laminate: {layup: "[0]", ply_thickness: 2 mm}
)",
                                           "iso.yaml");
  EXPECT_EQ(unnamed.material.name(), "material");
}

TEST(CaseFile, ReadMaterialIsReusableOnItsOwn) {
  const YAML::Node node = YAML::Load("{type: isotropic, E: 210 GPa, nu: 0.3}");
  const Material m = read_material(node, Where{"cli", "indenter_material", "", 1});
  EXPECT_EQ(m.name(), "indenter_material");
  EXPECT_DOUBLE_EQ(m.constants().E1, 210000.0);
  EXPECT_EQ(read_material(YAML::Load("steel"), Where{"cli", "m", "", 1}).name(), "steel");
}

TEST(CaseFile, SandwichPlyListStudy) {
  const CaseFile c =
      read_case_file(std::string(SHELLINDENT_SOURCE_DIR) + "/studies/sandwich_example.yaml");
  const auto& plies = c.laminate.plies;
  ASSERT_EQ(plies.size(), 11u);  // 4 face plies, adhesive, foam, adhesive, 4 face plies
  EXPECT_EQ(angles_of(c.laminate), (std::vector<double>{0, 90, 90, 0, 0, 0, 0, 90, 0, 0, 90}));
  EXPECT_EQ(plies[0].material.name(), "paper-carbon-epoxy");
  EXPECT_EQ(plies[4].material.name(), "adhesive");
  EXPECT_EQ(plies[5].material.name(), "foam");
  EXPECT_DOUBLE_EQ(plies[5].material.constants().E1, 180.0);
  EXPECT_EQ(plies[6].material.name(), "adhesive");
  EXPECT_EQ(plies[10].material.name(), "paper-carbon-epoxy");
  EXPECT_DOUBLE_EQ(plies[5].thickness, 5.0);
  EXPECT_NEAR(c.laminate.thickness(), 8 * 0.125 + 0.2 + 5.0, 1e-12);
  EXPECT_EQ(c.output.formats, (std::vector<OutputFormat>{OutputFormat::kCsv, OutputFormat::kVtu}));
  EXPECT_EQ(c.output.vtu_every, 5);
}

// The local-indentation study (issue 7) is cap_00_path.yaml with contact.local: yang_sun.
TEST(CaseFile, LocalIndentationStudy) {
  const std::string dir = std::string(SHELLINDENT_SOURCE_DIR) + "/studies/";
  const CaseFile local = read_case_file(dir + "cap_00_local.yaml");
  const CaseFile path = read_case_file(dir + "cap_00_path.yaml");
  EXPECT_EQ(local.contact.local, LocalContactModel::kYangSun);
  EXPECT_EQ(path.contact.local, LocalContactModel::kNone);
  EXPECT_EQ(local.mesh.size_apex, path.mesh.size_apex);
  EXPECT_EQ(local.path.depth_max, path.path.depth_max);
  EXPECT_EQ(local.output.dir, "results/cap_00_local/");
}

TEST(CaseFile, PlyListEntriesWithAnglesAndNamedLibraryMaterials) {
  const CaseFile c = parse_case_file(R"(
material: paper-carbon-epoxy
materials:
  skin: aluminium-2024-t3
laminate:
  plies:
    - {material: skin, thickness: 0.5 mm}
    - {thickness: 0.2 mm, angle: 30 deg}
    - {material: steel, thickness: 0.1 mm, angle: -0.5 rad}
)",
                                     "plies.yaml");
  const auto& plies = c.laminate.plies;
  ASSERT_EQ(plies.size(), 3u);
  EXPECT_EQ(plies[0].material.name(), "skin");
  EXPECT_DOUBLE_EQ(plies[0].material.constants().E1, 73100.0);
  EXPECT_EQ(plies[0].angle_deg, 0.0);
  EXPECT_EQ(plies[1].material.name(), "paper-carbon-epoxy");
  EXPECT_DOUBLE_EQ(plies[1].angle_deg, 30.0);
  EXPECT_EQ(plies[2].material.name(), "steel");
  EXPECT_NEAR(plies[2].angle_deg, -0.5 * 180.0 / 3.14159265358979323846, 1e-12);
}

TEST(CaseFile, ReferenceSurfaces) {
  const auto offset = [](const std::string& reference) {
    return parse_case_file(
               "material: paper-carbon-epoxy\n"
               "laminate: {layup: '[0/90]S', ply_thickness: 0.5 mm, reference: " +
                   reference + "}\n",
               "ref.yaml")
        .laminate.reference_offset;
  };
  EXPECT_DOUBLE_EQ(offset("mid"), 0.0);
  EXPECT_DOUBLE_EQ(offset("bottom"), -1.0);
  EXPECT_DOUBLE_EQ(offset("top"), 1.0);
  EXPECT_DOUBLE_EQ(offset("0.25 mm"), 0.25);
  EXPECT_DOUBLE_EQ(offset("-1 mm"), -1.0);
}

TEST(CaseFile, LayupWithItsOwnMaterial) {
  const CaseFile c = parse_case_file(R"(
material: steel
laminate: {layup: "[0/90]", ply_thickness: 1 mm, material: paper-carbon-epoxy}
)",
                                     "own.yaml");
  EXPECT_EQ(c.material.name(), "steel");
  EXPECT_EQ(c.laminate.plies[1].material.name(), "paper-carbon-epoxy");
}

TEST(CaseFile, OtherShellsIndentersAndOptions) {
  const std::string head =
      "material: paper-carbon-epoxy\n"
      "laminate: {layup: '[0/90]S', ply_thickness: 0.5 mm}\n";
  const CaseFile plate = parse_case_file(head + R"(
shell: {type: rectangular_plate, length_x: 100 mm, length_y: 50 mm, edge: simply_supported}
mesh: {element: bernstein4, symmetry: quarter}
kinematics: linear
indenter: {shape: superquadric, a: 5 mm, b: 6 mm, c: 7 mm, e1: 0.5, e2: 2, material: steel}
contact: {surface: mid, solver: active_set, local: vam, traction: interpolated, fbar: true}
path: {method: natural, depth_max: 2 mm, step: 0.5 mm, step_min: 0.01 mm, step_max: 1 mm,
       depths: [0.5 mm, 1 mm, 2 mm]}
output: {dir: out, vtu_every: 0, formats: [json]}
)",
                                         "plate.yaml");
  EXPECT_EQ(plate.shell.type, ShellType::kRectangularPlate);
  EXPECT_DOUBLE_EQ(plate.shell.length_x, 100.0);
  EXPECT_DOUBLE_EQ(plate.shell.length_y, 50.0);
  EXPECT_EQ(plate.shell.edge, EdgeCondition::kSimplySupported);
  EXPECT_EQ(plate.mesh.element, ElementType::kBernstein4);
  EXPECT_EQ(plate.mesh.symmetry, Symmetry::kQuarter);
  EXPECT_DOUBLE_EQ(plate.mesh.size_apex, 0.5);  // default kept
  EXPECT_EQ(plate.kinematics, Kinematics::kLinear);
  EXPECT_EQ(plate.indenter.shape, IndenterShape::kSuperquadric);
  EXPECT_DOUBLE_EQ(plate.indenter.c, 7.0);
  EXPECT_DOUBLE_EQ(plate.indenter.e1, 0.5);
  EXPECT_DOUBLE_EQ(plate.indenter.e2, 2.0);
  ASSERT_TRUE(plate.indenter.material.has_value());
  EXPECT_EQ(plate.indenter.material->name(), "steel");
  EXPECT_EQ(plate.contact.surface, ContactSurface::kMid);
  EXPECT_EQ(plate.contact.solver, ContactSolver::kActiveSet);
  EXPECT_EQ(plate.contact.local, LocalContactModel::kVam);
  EXPECT_EQ(plate.contact.traction, ContactTraction::kInterpolated);
  EXPECT_TRUE(plate.contact.fbar);
  EXPECT_EQ(plate.path.method, PathMethod::kNatural);
  EXPECT_DOUBLE_EQ(plate.path.step_min, 0.01);
  EXPECT_DOUBLE_EQ(plate.path.step_max, 1.0);
  EXPECT_EQ(plate.path.depths, (std::vector<double>{0.5, 1.0, 2.0}));
  EXPECT_EQ(plate.output.dir, "out");
  EXPECT_EQ(plate.output.vtu_every, 0);
  EXPECT_EQ(plate.output.formats, std::vector<OutputFormat>{OutputFormat::kJson});

  const CaseFile cylinder = parse_case_file(head + R"(
shell: {type: cylindrical_panel, radius: 100 mm, length: 200 mm, angle: 60 deg, edge: hinged}
indenter: {shape: cylinder, radius: 5 mm, length: 30 mm, material: rigid}
)",
                                            "cyl.yaml");
  EXPECT_EQ(cylinder.shell.type, ShellType::kCylindricalPanel);
  EXPECT_DOUBLE_EQ(cylinder.shell.angle_deg, 60.0);
  EXPECT_EQ(cylinder.shell.edge, EdgeCondition::kHinged);
  EXPECT_EQ(cylinder.indenter.shape, IndenterShape::kCylinder);
  EXPECT_DOUBLE_EQ(cylinder.indenter.length, 30.0);
  EXPECT_FALSE(cylinder.indenter.material.has_value());

  const CaseFile disc = parse_case_file(head + R"(
shell: {type: flat_circular_plate, radius: 40 mm}
indenter: {shape: flat_punch, radius: 5 mm, edge_radius: 0.5 mm}
)",
                                        "disc.yaml");
  EXPECT_EQ(disc.shell.type, ShellType::kFlatCircularPlate);
  EXPECT_DOUBLE_EQ(disc.shell.radius, 40.0);
  EXPECT_EQ(disc.shell.edge, EdgeCondition::kClamped);
  EXPECT_EQ(disc.indenter.shape, IndenterShape::kFlatPunch);
  EXPECT_DOUBLE_EQ(disc.indenter.edge_radius, 0.5);
}

TEST(CaseFile, LoadSectionIsOptionalAndConvertsUnits) {
  EXPECT_FALSE(parse_case_file(kMinimal, "t.yaml").load.has_value());
  const CaseFile apex = parse_case_file(
      std::string(kMinimal) + "load: {type: apex_force, force: 1 kN, steps: 4}\n", "t.yaml");
  ASSERT_TRUE(apex.load.has_value());
  EXPECT_EQ(apex.load->type, LoadType::kApexForce);
  EXPECT_DOUBLE_EQ(apex.load->force, 1000.0);
  EXPECT_EQ(apex.load->steps, 4);
  const CaseFile p = parse_case_file(
      std::string(kMinimal) + "load: {type: pressure, pressure: 100 kPa, follower: true}\n",
      "t.yaml");
  ASSERT_TRUE(p.load.has_value());
  EXPECT_EQ(p.load->type, LoadType::kPressure);
  EXPECT_DOUBLE_EQ(p.load->pressure, 0.1);
  EXPECT_TRUE(p.load->follower);
  EXPECT_EQ(p.load->steps, 10);
}

}  // namespace
}  // namespace si
