#include "core/units.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace si {
namespace {

TEST(Units, ConvertsToInternalUnits) {
  EXPECT_DOUBLE_EQ(parse_quantity("130 GPa", Dimension::kStress), 130000.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.475 mm", Dimension::kLength), 0.475);
  EXPECT_DOUBLE_EQ(parse_quantity("0.475mm", Dimension::kLength), 0.475);
  EXPECT_DOUBLE_EQ(parse_quantity("3.8e-3 m", Dimension::kLength), 3.8);
  EXPECT_DOUBLE_EQ(parse_quantity("1 in", Dimension::kLength), 25.4);
  EXPECT_DOUBLE_EQ(parse_quantity("45 deg", Dimension::kAngle), 45.0);
  EXPECT_NEAR(parse_quantity("3.14159265358979 rad", Dimension::kAngle), 180.0, 1e-10);
  EXPECT_DOUBLE_EQ(parse_quantity("2 kN", Dimension::kForce), 2000.0);
  EXPECT_DOUBLE_EQ(parse_quantity("1 J", Dimension::kEnergy), 1000.0);
  EXPECT_DOUBLE_EQ(parse_quantity("0.3", Dimension::kDimensionless), 0.3);
  EXPECT_NEAR(parse_quantity("1 ksi", Dimension::kStress), 6.894757293168361, 1e-12);
  // Fracture toughness, energy per crack area: 1 kJ/m^2 = 1 N/mm.
  EXPECT_DOUBLE_EQ(parse_quantity("0.5 N/mm", Dimension::kFractureToughness), 0.5);
  EXPECT_DOUBLE_EQ(parse_quantity("0.788 kJ/m^2", Dimension::kFractureToughness), 0.788);
  EXPECT_DOUBLE_EQ(parse_quantity("277 J/m^2", Dimension::kFractureToughness), 0.277);
  EXPECT_NEAR(parse_quantity("1 lbf/in", Dimension::kFractureToughness), 0.17512683524647637,
              1e-15);
  EXPECT_THROW(parse_quantity("0.5 MPa", Dimension::kFractureToughness), Error);
  EXPECT_THROW(parse_quantity("0.5", Dimension::kFractureToughness), Error);
}

TEST(Units, RefusesMissingWrongAndUnknownUnits) {
  for (const char* bad : {"130", "130 mm", "130 GXa", "", "GPa", "1e999 GPa"}) {
    try {
      parse_quantity(bad, Dimension::kStress);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::kInput);
      EXPECT_EQ(e.where().value, bad);
    }
  }
  EXPECT_THROW(parse_quantity("0.3 mm", Dimension::kDimensionless), Error);
}

TEST(Units, MessageSaysWhatIsWrong) {
  try {
    parse_quantity("3.8 GPa", Dimension::kLength);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'GPa' is a stress unit, expected a length"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace si
