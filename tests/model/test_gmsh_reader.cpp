#include "model/gmsh_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "mesh_test_support.hpp"

namespace si {
namespace {

using testing::expect_input_error;

// Hand-written MSH 4.1 file: unit square, 2 x 2 quadrangles, node tags 1-8 and 12, physical
// line "clamped" (x = 0), physical point "load" (corner (1, 1)), unnamed-free bottom lines.
const std::string kFixture =
    std::string(SHELLINDENT_SOURCE_DIR) + "/tests/model/data/quad_patch.msh";

std::string fixture_text() {
  std::ifstream in(kFixture);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Writes `text` to a temporary file named after the current test and returns its path.
std::string write_temp(const std::string& text) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto path = std::filesystem::temp_directory_path() /
                    (std::string("shellindent_") + info->name() + ".msh");
  std::ofstream(path) << text;
  return path.string();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(GmshReader, ReadsTheFixture) {
  const Mesh mesh = read_gmsh_msh4(kFixture);
  ASSERT_EQ(mesh.num_nodes(), 9);
  ASSERT_EQ(mesh.num_elements(), 4);
  EXPECT_NEAR(mesh_area(mesh), 1.0, 1e-15);
  EXPECT_EQ(mesh.nodes[8], Vector3d(0.5, 0.5, 0));  // tag 12 renumbered densely
  EXPECT_EQ(mesh.elements[0], (std::array<int, 4>{0, 4, 8, 7}));
  for (const Vector3d& d : mesh.directors) EXPECT_TRUE(d.isApprox(Vector3d::UnitZ()));
  testing::expect_set_is(mesh, "clamped", [](const Vector3d& p) { return p.x() == 0; });
  EXPECT_EQ(mesh.node_sets.at("load"), (std::vector<int>{2}));
  EXPECT_EQ(mesh.nodes[2], Vector3d(1, 1, 0));
  EXPECT_EQ(mesh.node_sets.size(), 2u);  // the surface group "plate" makes no node set
}

TEST(GmshReader, RejectsTriangles) {
  const std::string path = write_temp(replaced(fixture_text(), "\n2 1 3 4\n", "\n2 1 2 4\n"));
  expect_input_error([&] { read_gmsh_msh4(path); },
                     {path + ":63:",
                      "only quadrilateral surface meshes are supported; element 10 is a 3-node "
                      "triangle"});
}

TEST(GmshReader, RejectsATruncatedFile) {
  const std::string text = fixture_text();
  const std::string path = write_temp(text.substr(0, text.find("0.5 0.5 0")));
  expect_input_error([&] { read_gmsh_msh4(path); }, {path, "ends early", "node coordinate"});
}

TEST(GmshReader, RejectsMsh22) {
  const std::string path = write_temp(replaced(fixture_text(), "4.1 0 8", "2.2 0 8"));
  expect_input_error([&] { read_gmsh_msh4(path); },
                     {path + ":2:", "MSH 2.2 is not supported, export as 4.1"});
}

TEST(GmshReader, RejectsBinaryAndMissingFiles) {
  const std::string path = write_temp(replaced(fixture_text(), "4.1 0 8", "4.1 1 8"));
  expect_input_error([&] { read_gmsh_msh4(path); }, {"binary"});
  expect_input_error([] { read_gmsh_msh4("/nonexistent/mesh.msh"); },
                     {"/nonexistent/mesh.msh", "cannot open"});
}

TEST(GmshReader, RejectsInconsistentOrientation) {
  const std::string path = write_temp(replaced(fixture_text(), "13 8 12 7 4", "13 8 4 7 12"));
  expect_input_error([&] { read_gmsh_msh4(path); },
                     {path + ":66:", "elements 12 (line 65) and 13", "inconsistent"});
}

TEST(GmshReader, NamesTheGmshElementOfABadQuadrangle) {
  const std::string path = write_temp(replaced(fixture_text(), "13 8 12 7 4", "13 8 12 12 4"));
  expect_input_error([&] { read_gmsh_msh4(path); },
                     {path + ":66:", "repeats node", "[Gmsh element 13]"});
}

TEST(GmshReader, RejectsUndefinedNodesAndBadNumbers) {
  const std::string undefined = write_temp(replaced(fixture_text(), "13 8 12 7 4", "13 8 12 7 99"));
  expect_input_error([&] { read_gmsh_msh4(undefined); }, {":66:", "element 13", "node 99"});
  const std::string bad = write_temp(replaced(fixture_text(), "0.5 0.5 0", "0.5 zero 0"));
  expect_input_error([&] { read_gmsh_msh4(bad); }, {"expected a number", "'zero'"});
}

}  // namespace
}  // namespace si
