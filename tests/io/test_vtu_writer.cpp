#include "io/vtu_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

#include "../model/test_meshes.hpp"
#include "core/error.hpp"
#include "model/assembler.hpp"

namespace si {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Minimal XML well-formedness: every start tag is closed by the matching end tag, in order.
bool tags_balanced(const std::string& xml) {
  std::vector<std::string> open;
  const std::regex tag(R"(<(/?)([A-Za-z]+)[^>]*?(/?)>)");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), tag); it != std::sregex_iterator();
       ++it) {
    const std::string closing = (*it)[1], name = (*it)[2], self = (*it)[3];
    if (!self.empty()) continue;
    if (closing.empty()) {
      open.push_back(name);
    } else {
      if (open.empty() || open.back() != name) return false;
      open.pop_back();
    }
  }
  return open.empty();
}

std::vector<std::string> array_names(const std::string& xml) {
  std::vector<std::string> names;
  const std::regex name(R"re(<DataArray[^>]*Name="([^"]+)")re");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), name); it != std::sregex_iterator();
       ++it)
    names.push_back((*it)[1]);
  return names;
}

TEST(VtuWriter, WritesAWellFormedGridWithAllFields) {
  const Mesh m = testing::square_plate(3, 2);
  std::vector<NodeState> state = reference_state(m);
  state[5].u = Vector3d(0.5, 0, 0.25);
  VtuFields fields;
  fields.point_data["thickness"] = Eigen::VectorXd::Constant(m.num_nodes(), 0.1);
  fields.point_data["R"] = Eigen::MatrixXd::Zero(m.num_nodes(), 6);
  fields.cell_data["energy"] = Eigen::VectorXd::LinSpaced(m.num_elements(), 0, 1);
  const std::string path = (std::filesystem::temp_directory_path() / "si_test_grid.vtu").string();
  write_vtu(path, m, state, fields);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const std::string xml = read(path);
  EXPECT_TRUE(tags_balanced(xml));
  EXPECT_NE(xml.find("<?xml version=\"1.0\"?>"), std::string::npos);
  EXPECT_NE(xml.find("NumberOfPoints=\"12\" NumberOfCells=\"6\""), std::string::npos);
  EXPECT_EQ(array_names(xml),
            (std::vector<std::string>{"connectivity", "offsets", "types", "displacement",
                                      "director", "R", "thickness", "energy"}));
  EXPECT_NE(xml.find("NumberOfComponents=\"6\""), std::string::npos);
  // Node 5 (x = 1/3, y = 1/2) is written at its reference position, to full precision, and its
  // displacement in the array `displacement` (ParaView's Warp By Vector adds them once).
  std::ostringstream point;
  point.precision(17);
  point << ' ' << 1.0 / 3.0 << ' ' << 0.5 << ' ' << 0 << '\n';
  EXPECT_NE(xml.find(point.str()), std::string::npos) << point.str();
  EXPECT_NE(xml.find(" 0.5 0 0.25\n"), std::string::npos);
  // The tag-balance check itself fails on a broken document.
  EXPECT_FALSE(tags_balanced("<a><b></a></b>"));
  EXPECT_FALSE(tags_balanced("<a><b/>"));
  std::filesystem::remove(path);
}

TEST(VtuWriter, ReferenceCoordinatesAndBadFields) {
  const Mesh m = testing::square_plate(1, 1);
  std::vector<NodeState> state = reference_state(m);
  state[3].u = Vector3d(7, 7, 7);
  VtuFields fields;
  const std::string path = (std::filesystem::temp_directory_path() / "si_test_ref.vtu").string();
  write_vtu(path, m, state, fields);
  const std::string xml = read(path);
  // Node 3 at its reference position (1, 1, 0), not at X + u = (8, 8, 7) (always: points are
  // the reference configuration).
  EXPECT_EQ(xml.find("8 8 7"), std::string::npos);
  EXPECT_NE(xml.find("1 1 0\n"), std::string::npos);
  std::filesystem::remove(path);
  fields.point_data["wrong"] = Eigen::MatrixXd::Zero(3, 1);
  EXPECT_THROW(write_vtu(path, m, state, fields), Error);
  fields.point_data.clear();
  fields.cell_data["wrong"] = Eigen::MatrixXd::Zero(1, 2);
  EXPECT_THROW(write_vtu(path, m, state, fields), Error);
  fields.cell_data.clear();
  fields.point_data["displacement"] = Eigen::MatrixXd::Zero(4, 3);
  EXPECT_THROW(write_vtu(path, m, state, fields), Error);
  // A directory that cannot be made (its parent is a file): an input error, nothing written.
  const std::string file = (std::filesystem::temp_directory_path() / "si_test_vtu_file").string();
  std::ofstream(file) << "a file";
  EXPECT_THROW(write_vtu(file + "/x.vtu", m, state, {}), Error);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace si
