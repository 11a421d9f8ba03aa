// Ply strengths and toughness in case files (docs/case-file.md `material`): nested or flat, with
// units, each optional; bad values refused naming the file, line, key and value.
#include "io/material_reader.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace si {
namespace {

const std::string kElastic =
    "type: orthotropic\nE1: 130 GPa\nE2: 10 GPa\nE3: 10 GPa\nG12: 6 GPa\nG13: 3 GPa\n"
    "G23: 6 GPa\nnu12: 0.3\nnu13: 0.5\nnu23: 0.3\n";  // lines 1-10

Material read(const std::string& yaml) {
  return read_material(YAML::Load(yaml), Where{"case.yaml", "material", "", 1});
}

void expect_error(const std::string& yaml, const std::string& key, const std::string& value,
                  int line, const std::string& reason_part) {
  try {
    read(yaml);
    ADD_FAILURE() << "accepted:\n" << yaml;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().file, "case.yaml");
    EXPECT_EQ(e.where().key, key);
    EXPECT_EQ(e.where().value, value);
    EXPECT_EQ(e.where().line, line);
    EXPECT_NE(e.reason().find(reason_part), std::string::npos) << e.reason();
  }
}

TEST(MaterialReader, NestedStrengthsAndToughnessWithUnits) {
  const Material m = read(kElastic +
                          "strengths: {X_T: 1.5 GPa, X_C: 900 MPa, Y_T: 27 MPa, S_12: 80 MPa}\n"
                          "toughness: {G_Ic: 277 J/m^2, G_IIc: 0.788 kJ/m^2}\n");
  EXPECT_DOUBLE_EQ(*m.strengths().get(StrengthKey::kXT), 1500.0);
  EXPECT_DOUBLE_EQ(*m.strengths().get(StrengthKey::kXC), 900.0);
  EXPECT_DOUBLE_EQ(*m.strengths().get(StrengthKey::kS12), 80.0);
  EXPECT_FALSE(m.strengths().get(StrengthKey::kZT).has_value());
  EXPECT_DOUBLE_EQ(*m.toughness().get(ToughnessKey::kGIc), 0.277);
  EXPECT_DOUBLE_EQ(*m.toughness().get(ToughnessKey::kGIIc), 0.788);
}

TEST(MaterialReader, FlatKeysAndNoneAtAll) {
  const Material flat = read(kElastic + "Y_C: 200 MPa\nS_23: 75 MPa\nG_IIc: 0.5 N/mm\n");
  EXPECT_DOUBLE_EQ(*flat.strengths().get(StrengthKey::kYC), 200.0);
  EXPECT_DOUBLE_EQ(*flat.strengths().get(StrengthKey::kS23), 75.0);
  EXPECT_DOUBLE_EQ(*flat.toughness().get(ToughnessKey::kGIIc), 0.5);
  const Material none = read(kElastic);
  EXPECT_TRUE(none.strengths().empty());
  EXPECT_TRUE(none.toughness().empty());
  const Material iso = read("{type: isotropic, E: 70 GPa, nu: 0.3, X_T: 400 MPa}");
  EXPECT_DOUBLE_EQ(*iso.strengths().get(StrengthKey::kXT), 400.0);
}

TEST(MaterialReader, LibraryMaterialsCarryTheirFailureData) {
  const Material im7 = read("im7-8552");
  EXPECT_DOUBLE_EQ(*im7.strengths().get(StrengthKey::kYT), 62.3);
  EXPECT_DOUBLE_EQ(*im7.toughness().get(ToughnessKey::kGIIc), 0.788);
  EXPECT_FALSE(read("as4-3501-6").toughness().get(ToughnessKey::kGIIc).has_value());
  // A `materials:` key renames, keeping the failure data.
  const std::vector<Material> named =
      read_material_map(YAML::Load("face: t300-914c\n"), Where{"case.yaml", "materials", "", 1});
  EXPECT_EQ(named[0].name(), "face");
  EXPECT_DOUBLE_EQ(*named[0].strengths().get(StrengthKey::kXC), 900.0);
}

TEST(MaterialReader, NegativeStrengthIsRefusedNamingTheKey) {
  expect_error(kElastic + "strengths: {X_T: 1500 MPa,\n            Y_T: -27 MPa}\n",
               "material.strengths.Y_T", "-27 MPa", 12, "Y_T must be positive");
  expect_error(kElastic + "G_IIc: 0 N/mm\n", "material.G_IIc", "0 N/mm", 11,
               "G_IIc must be positive");
}

TEST(MaterialReader, BadUnitsUnknownKeysAndDuplicates) {
  expect_error(kElastic + "strengths: {X_T: 1500 N/mm}\n", "material.strengths.X_T", "1500 N/mm",
               11, "wrong unit");
  expect_error(kElastic + "toughness: {G_IIc: 0.5 MPa}\n", "material.toughness.G_IIc", "0.5 MPa",
               11, "wrong unit");
  expect_error(kElastic + "strengths: {XT: 1500 MPa}\n", "material.strengths.XT", "1500 MPa", 11,
               "did you mean 'X_T'");
  expect_error(kElastic + "strengths: {S_12: 80 MPa}\nS_12: 81 MPa\n", "material.S_12", "81 MPa",
               12, "given twice");
}

}  // namespace
}  // namespace si
