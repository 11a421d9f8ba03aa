#include "material/material_library.hpp"

#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"

namespace si {
namespace {

TEST(MaterialLibrary, EveryMaterialConstructsAndIsNamedAfterItsKey) {
  const auto names = library_material_names();
  ASSERT_FALSE(names.empty());
  for (const auto& name : names) {
    const Material m = library_material(name);  // validation runs in the factories
    EXPECT_EQ(m.name(), name);
  }
}

TEST(MaterialLibrary, NamesAreUnique) {
  const auto names = library_material_names();
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
}

// Source paper, Table 1, as printed (G23 = 6 GPa; not transversely isotropic).
TEST(MaterialLibrary, PaperCarbonEpoxyIsTable1) {
  const auto c = library_material("paper-carbon-epoxy").constants();
  EXPECT_DOUBLE_EQ(c.E1, 130000.0);
  EXPECT_DOUBLE_EQ(c.E2, 10000.0);
  EXPECT_DOUBLE_EQ(c.E3, 10000.0);
  EXPECT_DOUBLE_EQ(c.G12, 6000.0);
  EXPECT_DOUBLE_EQ(c.G13, 3000.0);
  EXPECT_DOUBLE_EQ(c.G23, 6000.0);
  EXPECT_DOUBLE_EQ(c.nu12, 0.3);
  EXPECT_DOUBLE_EQ(c.nu13, 0.5);
  EXPECT_DOUBLE_EQ(c.nu23, 0.3);
}

TEST(MaterialLibrary, IsotropicMetals) {
  const Material steel = library_material("steel");
  EXPECT_TRUE(steel.is_isotropic());
  EXPECT_DOUBLE_EQ(steel.constants().E1, 210000.0);
  EXPECT_DOUBLE_EQ(steel.constants().nu12, 0.3);
  const Material al = library_material("aluminium-2024-t3");
  EXPECT_DOUBLE_EQ(al.constants().E1, 73100.0);
  EXPECT_DOUBLE_EQ(al.constants().nu12, 0.33);
}

TEST(MaterialLibrary, UnknownNameListsTheKnownOnes) {
  try {
    library_material("unobtainium");
    FAIL() << "accepted an unknown name";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().value, "unobtainium");
    const std::string message = e.what();
    for (const auto& name : library_material_names())
      EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace si
