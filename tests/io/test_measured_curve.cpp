// Measured force-travel curves (io/measured_curve.hpp): units in the header converted, and every
// kind of bad file refused with the file, the line, the column and the value.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "io/measured_curve.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

std::string write(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / "shellindent_measured_curve";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

// The message of the input error thrown by `f`, or "" if none.
template <class F>
std::string input_error(F f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    return e.what();
  }
  return "";
}

TEST(MeasuredCurve, SplitsNamesAndUnitsInTheThreeForms) {
  EXPECT_EQ(split_column_name("travel_mm").name, "travel");
  EXPECT_EQ(split_column_name("travel_mm").unit, "mm");
  EXPECT_EQ(split_column_name(" force (kN) ").unit, "kN");
  EXPECT_EQ(split_column_name(" force (kN) ").name, "force");
  EXPECT_EQ(split_column_name("load [lbf]").unit, "lbf");
  EXPECT_EQ(split_column_name("apex_w_mm").name, "apex_w");
  EXPECT_EQ(split_column_name("k11_per_mm").unit, "mm");  // a suffix that is a unit is one
  EXPECT_EQ(split_column_name("max_force").unit, "");     // "force" is not a unit
}

TEST(MeasuredCurve, ConvertsToMillimetresAndNewtons) {
  const std::string f = write("kn.csv",
                              "# a test record\n"
                              "time (s), travel (in), force (kN)\n"
                              "0, 0, 0\n1, 0.01, 0.5\n2, 0.02, 1.25\n3, 0.04, 2.5\n");
  const MeasuredCurve m = read_measured_curve(f, "", "", 3);
  ASSERT_EQ(m.travel.size(), 4u);
  EXPECT_DOUBLE_EQ(m.travel[2], 0.02 * 25.4);
  EXPECT_DOUBLE_EQ(m.force[2], 1250.0);
  EXPECT_EQ(m.x_header, "travel (in)");  // the first length column, not time
  EXPECT_EQ(m.lines[0], 3);
  const MeasuredCurve named = read_measured_curve(f, "travel", "force (kN)", 3);
  EXPECT_DOUBLE_EQ(named.force[3], 2500.0);
}

TEST(MeasuredCurve, RefusesBadFilesNamingLineColumnAndValue) {
  struct Bad {
    std::string text, where, why;
  };
  const Bad cases[] = {
      {"travel_mm,force_N\n0.1,10\n0.3,20\n0.2,30\n0.4,40\n", ":4: travel_mm = '0.2'",
       "increase strictly"},
      {"travel_mm,force_N\n0.1,10\n0.2,1e999\n0.3,30\n0.4,40\n", ":3: force_N = '1e999'",
       "not a finite number (column 2)"},
      {"travel_mm,force_N\n0.1,10\n0.2,nan\n0.3,30\n0.4,40\n", ":3: force_N = 'nan'",
       "not a number (column 2)"},
      {"travel_mm,force_N\n0.1,10\n0.2,abc\n0.3,30\n0.4,40\n", ":3: force_N = 'abc'",
       "not a number"},
      {"travel_mm,force (MPa)\n0.1,10\n0.2,20\n0.3,30\n0.4,40\n", ":1: header",
       "no column with a force unit"},
      {"travel (mm),force\n0.1,10\n0.2,20\n0.3,30\n0.4,40\n", "", "no column with a force unit"},
      {"travel_mm,force_N\n-0.1,10\n0.2,20\n0.3,30\n0.4,40\n", ":2: travel_mm = '-0.1'",
       "negative travel"},
      {"travel_mm,force_N\n0.1,10\n0.2,20\n0.3,30\n", ":4: force_N = '3 points'",
       "needs at least 4"},
  };
  int k = 0;
  for (const Bad& b : cases) {
    const std::string f = write("bad" + std::to_string(k++) + ".csv", b.text);
    const std::string m = input_error([&] { read_measured_curve(f, "", "", 4); });
    EXPECT_NE(m.find(f + b.where), std::string::npos) << m;
    EXPECT_NE(m.find(b.why), std::string::npos) << m;
  }
  // A unit of the wrong kind in a column chosen by name, and a column without a unit.
  const std::string f =
      write("units.csv", "travel_mm,force (MPa),load\n0.1,1,1\n0.2,2,2\n0.3,3,3\n0.4,4,4\n");
  std::string m = input_error([&] { read_measured_curve(f, "travel", "force", 4); });
  EXPECT_NE(m.find("column 2 = 'force (MPa)'"), std::string::npos) << m;
  EXPECT_NE(m.find("expected a force"), std::string::npos) << m;
  m = input_error([&] { read_measured_curve(f, "travel", "load", 4); });
  EXPECT_NE(m.find("column 3 = 'load'"), std::string::npos) << m;
  EXPECT_NE(m.find("has no unit"), std::string::npos) << m;
  m = input_error([&] { read_measured_curve(f, "travle", "", 4); });
  EXPECT_NE(m.find("did you mean 'travel_mm'"), std::string::npos) << m;
  EXPECT_NE(m.find("column = 'travle'"), std::string::npos) << m;
}

}  // namespace
}  // namespace si
