// Numeric case-file keys set from outside the file (io/case_overrides.hpp): the keys of a case,
// a library material written out when one of its constants is set (the plies still use it), and
// unknown names refused with a suggestion.
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/case_file.hpp"
#include "io/case_overrides.hpp"
#include "material/material_library.hpp"

namespace si {
namespace {

const char* kCase =
    "material: paper-carbon-epoxy\n"
    "materials: {core: {type: isotropic, E: 180 MPa, nu: 0.3}}\n"
    "laminate: {layup: \"[0/90]S\", ply_thickness: 0.475 mm, material: paper-carbon-epoxy}\n"
    "indenter: {shape: sphere, radius: 12.7 mm, material: steel}\n";

CaseFile read_with(const YAML::Node& root) {
  YAML::Emitter e;
  e << root;
  return parse_case_file(e.c_str(), "case.yaml");
}

TEST(CaseOverrides, ListsTheConstantsOfEveryMaterialWithTheirValues) {
  const YAML::Node root = YAML::Load(kCase);
  const auto keys = numeric_keys(root, "case.yaml");
  const NumericKey& e3 = find_numeric_key(keys, "material.E3", Where{});
  EXPECT_DOUBLE_EQ(e3.value, library_material("paper-carbon-epoxy").constants().E3);
  EXPECT_EQ(e3.dimension, Dimension::kStress);
  EXPECT_EQ(find_numeric_key(keys, "material.nu23", Where{}).dimension, Dimension::kDimensionless);
  EXPECT_DOUBLE_EQ(find_numeric_key(keys, "materials.core.E", Where{}).value, 180.0);
  EXPECT_DOUBLE_EQ(find_numeric_key(keys, "indenter.material.E", Where{}).value, 210000.0);
  EXPECT_DOUBLE_EQ(find_numeric_key(keys, "laminate.ply_thickness", Where{}).value, 0.475);
}

// Setting E3 of a library material: the case read back has the new E3 in every ply (the
// laminate names the material by its library name) and the library's other constants.
TEST(CaseOverrides, SettingALibraryConstantKeepsThePliesOnIt) {
  const YAML::Node root = YAML::Load(kCase);
  const CaseFile c = read_with(
      with_numeric_values(root, {{"material.E3", Dimension::kStress, 7654.321}}, "case.yaml"));
  const EngineeringConstants lib = library_material("paper-carbon-epoxy").constants();
  EXPECT_DOUBLE_EQ(c.material.constants().E3, 7654.321);
  EXPECT_DOUBLE_EQ(c.material.constants().G13, lib.G13);
  for (const auto& ply : c.laminate.plies) EXPECT_DOUBLE_EQ(ply.material.constants().E3, 7654.321);
  const CaseFile steel = read_with(with_numeric_values(
      root, {{"indenter.material.nu", Dimension::kDimensionless, 0.25}}, "case.yaml"));
  EXPECT_DOUBLE_EQ(steel.indenter.material->constants().nu12, 0.25);
  EXPECT_DOUBLE_EQ(steel.indenter.material->constants().E1, 210000.0);
}

TEST(CaseOverrides, UnknownNameGetsASuggestionAndTheList) {
  const auto keys = numeric_keys(YAML::Load(kCase), "case.yaml");
  try {
    find_numeric_key(keys, "materal.E3", Where{"command line", "--param", "materal.E3", 0});
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_NE(m.find("did you mean 'material.E3'"), std::string::npos) << m;
    EXPECT_NE(m.find("indenter.material.nu"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace si
