// The Gmsh reader: the hand-written fixture, the Gmsh 4.8 twins (4.1 text, 4.1 binary, 2.2
// text of tests/model/data/gmsh_plate.geo) read identically, and every refusal names the file,
// the line (or byte) and the Gmsh element.
#include "model/gmsh_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mesh_test_support.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

using testing::expect_input_error;

const std::string kData = std::string(SHELLINDENT_SOURCE_DIR) + "/tests/model/data/";

// Hand-written MSH 4.1 file: unit square, 2 x 2 quadrangles, node tags 1-8 and 12, physical
// line "clamped" (x = 0), physical point "load" (corner (1, 1)), physical surface "plate".
const std::string kFixture = kData + "quad_patch.msh";

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Writes `text` to a temporary file named after the current test (and `suffix`).
std::string write_temp(const std::string& text, const std::string& suffix = "") {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto path = std::filesystem::temp_directory_path() /
                    (std::string("shellindent_") + info->name() + suffix + ".msh");
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

Mesh read(const std::string& path) {
  return read_gmsh_mesh(path).mesh;
}

// A minimal MSH 4.1 text file (no entities, no groups): nodes tagged 1..n, quads tagged 1..m.
std::string simple_msh(const std::vector<Vector3d>& nodes,
                       const std::vector<std::array<int, 4>>& quads) {
  std::ostringstream os;
  os.precision(17);
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 " << nodes.size() << " 1 " << nodes.size()
     << "\n2 1 0 " << nodes.size() << "\n";
  for (size_t k = 0; k < nodes.size(); ++k) os << k + 1 << "\n";
  for (const auto& p : nodes) os << p.x() << " " << p.y() << " " << p.z() << "\n";
  os << "$EndNodes\n$Elements\n1 " << quads.size() << " 1 " << quads.size() << "\n2 1 3 "
     << quads.size() << "\n";
  for (size_t k = 0; k < quads.size(); ++k)
    os << k + 1 << " " << quads[k][0] << " " << quads[k][1] << " " << quads[k][2] << " "
       << quads[k][3] << "\n";
  os << "$EndElements\n";
  return os.str();
}

TEST(GmshReader, ReadsTheFixture) {
  const ImportedMesh imported = read_gmsh_mesh(kFixture);
  const Mesh& mesh = imported.mesh;
  EXPECT_TRUE(imported.warnings.empty());
  ASSERT_EQ(mesh.num_nodes(), 9);
  ASSERT_EQ(mesh.num_elements(), 4);
  EXPECT_NEAR(mesh_area(mesh), 1.0, 1e-15);
  EXPECT_EQ(mesh.nodes[8], Vector3d(0.5, 0.5, 0));  // tag 12 renumbered densely
  EXPECT_EQ(mesh.elements[0], (std::array<int, 4>{0, 4, 8, 7}));
  for (const Vector3d& d : mesh.directors) EXPECT_TRUE(d.isApprox(Vector3d::UnitZ()));
  testing::expect_set_is(mesh, "clamped", [](const Vector3d& p) { return p.x() == 0; });
  EXPECT_EQ(mesh.node_sets.at("load"), (std::vector<int>{2}));
  EXPECT_EQ(mesh.nodes[2], Vector3d(1, 1, 0));
  // The surface group is a node set and an element set.
  EXPECT_EQ(mesh.node_sets.at("plate").size(), 9u);
  EXPECT_EQ(mesh.element_sets.at("plate"), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(mesh.node_sets.size(), 3u);
}

// Gmsh 4.8 wrote the three files from one .geo: the same mesh in three encodings.
TEST(GmshReader, GmshBinaryTextAnd22TwinsReadIdentically) {
  const Mesh text = read(kData + "gmsh_plate_41.msh");
  const Mesh binary = read(kData + "gmsh_plate_41_binary.msh");
  const Mesh legacy = read(kData + "gmsh_plate_22.msh");
  ASSERT_EQ(text.num_elements(), 8);
  ASSERT_EQ(text.num_nodes(), 15);
  EXPECT_NEAR(mesh_area(text), 2.0, 1e-12);
  // Gmsh prints 16 significant digits: the binary doubles may differ in the last bit.
  ASSERT_EQ(binary.num_nodes(), text.num_nodes());
  for (int n = 0; n < text.num_nodes(); ++n)
    EXPECT_NEAR((binary.nodes[n] - text.nodes[n]).norm(), 0, 1e-15) << n;
  EXPECT_EQ(legacy.nodes, text.nodes);
  for (const Mesh* other : {&binary, &legacy}) {
    EXPECT_EQ(other->elements, text.elements);
    EXPECT_EQ(other->node_sets, text.node_sets);
    EXPECT_EQ(other->element_sets, text.element_sets);
  }
  // Named groups, one with a space in its name.
  testing::expect_set_is(text, "clamped", [](const Vector3d& p) { return p.x() == 0; });
  testing::expect_set_is(text, "loaded edge", [](const Vector3d& p) { return p.x() == 2; });
  testing::expect_set_is(text, "corner", [](const Vector3d& p) { return p == Vector3d(2, 1, 0); });
  EXPECT_EQ(text.element_sets.at("plate").size(), 8u);
}

TEST(GmshReader, RefusesTrianglesSayingWhatToDo) {
  const std::string path = write_temp(replaced(file_text(kFixture), "\n2 1 3 4\n", "\n2 1 2 4\n"));
  expect_input_error([&] { read(path); }, {path + ":63:", "element 10 is a 3-node triangle",
                                           "no triangle shell", "Recombine"});
}

TEST(GmshReader, RefusesHigherOrderVolumeAndUnknownElements) {
  const std::string text = file_text(kFixture);
  const std::string quad9 = write_temp(replaced(text, "\n2 1 3 4\n", "\n2 1 10 4\n"), "9");
  expect_input_error([&] { read(quad9); },
                     {quad9 + ":63:", "element 10 is a 9-node quadrangle", "ElementOrder = 1"});
  const std::string volume = write_temp(replaced(text, "\n2 1 3 4\n", "\n3 1 4 4\n"), "vol");
  expect_input_error([&] { read(volume); }, {volume + ":63:", "volume element"});
  const std::string unknown = write_temp(replaced(text, "\n2 1 3 4\n", "\n2 1 99 4\n"), "99");
  expect_input_error([&] { read(unknown); }, {unknown + ":63:", "element type 99"});
}

TEST(GmshReader, RefusesTruncatedFiles) {
  const std::string text = file_text(kFixture);
  const std::string path = write_temp(text.substr(0, text.find("0.5 0.5 0") + 7));
  expect_input_error([&] { read(path); }, {path, "ends early", "node coordinate"});
  const std::string no_end = write_temp(text.substr(0, text.find("$EndElements")), "end");
  expect_input_error([&] { read(no_end); }, {no_end, "ends early", "$EndElements"});
  const std::string binary = file_text(kData + "gmsh_plate_41_binary.msh");
  const std::string cut = write_temp(binary.substr(0, binary.find("$EndNodes") - 20), "bin");
  // Binary blocks have exact sizes: the bound on the count catches the cut first.
  expect_input_error([&] { read(cut); }, {cut, "truncated file?", "(at byte"});
}

TEST(GmshReader, RefusesUnsupportedVersionsAndEncodings) {
  const std::string text = file_text(kFixture);
  for (const char* version : {"4.0", "3.0", "2.1"}) {
    const std::string path =
        write_temp(replaced(text, "4.1 0 8", std::string(version) + " 0 8"), version);
    expect_input_error([&] { read(path); },
                       {path + ":2:", std::string("MSH version ") + version, "export as 4.1"});
  }
  const std::string binary22 = write_temp(replaced(text, "4.1 0 8", "2.2 1 8"), "b22");
  expect_input_error([&] { read(binary22); }, {"binary MSH 2.2"});
  std::string swapped = file_text(kData + "gmsh_plate_41_binary.msh");
  const size_t mark = swapped.find("4.1 1 8\n") + 8;
  swapped.replace(mark, 4, std::string("\0\0\0\1", 4));
  const std::string path = write_temp(swapped, "swap");
  expect_input_error([&] { read(path); }, {"other byte order"});
  expect_input_error([] { read("/nonexistent/mesh.msh"); },
                     {"/nonexistent/mesh.msh", "cannot open"});
  const std::string not_msh = write_temp("material: steel\n", "yaml");
  expect_input_error([&] { read(not_msh); }, {":1:", "not a Gmsh MSH file"});
}

// A count larger than the file could hold is refused before anything is allocated.
TEST(GmshReader, RefusesCountsTheFileCannotHold) {
  const std::string text =
      write_temp(replaced(file_text(kFixture), "9 9 1 12", "9 999999999999 1 12"));
  expect_input_error([&] { read(text); }, {text + ":23:", "999999999999", "cannot fit"});
  std::string binary = file_text(kData + "gmsh_plate_41_binary.msh");
  const size_t at = binary.find("$Nodes\n") + 7;
  const unsigned long long huge = 1ull << 40;
  binary.replace(at, 8, std::string(reinterpret_cast<const char*>(&huge), 8));
  const std::string path = write_temp(binary, "bin");
  expect_input_error([&] { read(path); }, {path, "node blocks", "(at byte"});
}

TEST(GmshReader, RefusesUndefinedAndDuplicateNodeTags) {
  const std::string text = file_text(kFixture);
  const std::string undefined = write_temp(replaced(text, "13 8 12 7 4", "13 8 12 7 99"), "u");
  expect_input_error([&] { read(undefined); },
                     {":66:", "element 13", "node 99", "does not define"});
  const std::string twice = write_temp(replaced(text, "\n12\n0.5 0.5 0", "\n5\n0.5 0.5 0"), "d");
  expect_input_error([&] { read(twice); }, {"node tag 5 is defined twice"});
  const std::string bad = write_temp(replaced(text, "0.5 0.5 0", "0.5 zero 0"), "n");
  expect_input_error([&] { read(bad); }, {"expected a number", "'zero'"});
}

TEST(GmshReader, RefusesDegenerateAndInvertedElements) {
  const std::string text = file_text(kFixture);
  const std::string repeated = write_temp(replaced(text, "13 8 12 7 4", "13 8 12 12 4"), "r");
  expect_input_error([&] { read(repeated); },
                     {repeated + ":66:", "element 13 (line 66)", "repeats node 12", "degenerate"});
  // A bow-tie: the corners of element 10 out of order.
  const std::string bowtie = write_temp(replaced(text, "10 1 5 12 8", "10 1 12 5 8"), "b");
  expect_input_error([&] { read(bowtie); },
                     {bowtie + ":63:", "element 10 (line 63)", "inverted or degenerate"});
}

TEST(GmshReader, FlippedElementIsReportedOrReversedOnRequest) {
  const std::string path = write_temp(replaced(file_text(kFixture), "13 8 12 7 4", "13 8 4 7 12"));
  expect_input_error([&] { read(path); }, {path + ":66:", "element 13 (line 66)",
                                           "oriented opposite to its neighbours", "mesh.reorient"});
  GmshReadOptions reorient;
  reorient.reorient = true;
  const ImportedMesh fixed = read_gmsh_mesh(path, reorient);
  const Mesh original = read(kFixture);
  EXPECT_EQ(fixed.mesh.elements, original.elements);
  EXPECT_EQ(fixed.mesh.directors, original.directors);
  ASSERT_EQ(fixed.warnings.size(), 1u);
  EXPECT_NE(fixed.warnings[0].find("reversed 1 element(s)"), std::string::npos);
  EXPECT_NE(fixed.warnings[0].find("Gmsh element(s) 13"), std::string::npos);
  // flip turns the whole mesh over.
  GmshReadOptions flip;
  flip.flip = true;
  const Mesh flipped = read_gmsh_mesh(kFixture, flip).mesh;
  for (const Vector3d& d : flipped.directors) EXPECT_EQ(d, Vector3d(0, 0, -1));
  EXPECT_EQ(flipped.elements[0], (std::array<int, 4>{0, 7, 8, 4}));
}

TEST(GmshReader, RefusesANonManifoldEdge) {
  // Three quadrangles on the edge (2, 5): two in the plane, one standing up.
  const std::string path = write_temp(simple_msh(
      {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}, {1, 0, 1}, {1, 1, 1}},
      {{1, 2, 5, 4}, {2, 3, 6, 5}, {2, 7, 8, 5}}));
  expect_input_error([&] { read(path); }, {path, "element 1", "edge between nodes 2 and 5",
                                           "element 3", "non-manifold"});
}

TEST(GmshReader, RefusesAMoebiusStrip) {
  const double pi = std::acos(-1.0);
  const int n = 16;
  std::vector<Vector3d> nodes;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * pi * i / n;
    const Vector3d centre(5 * std::cos(t), 5 * std::sin(t), 0);
    const Vector3d width = 0.5 * (std::cos(t / 2) * Vector3d(std::cos(t), std::sin(t), 0) +
                                  std::sin(t / 2) * Vector3d::UnitZ());
    nodes.push_back(centre + width);  // tag 2i + 1
    nodes.push_back(centre - width);  // tag 2i + 2
  }
  std::vector<std::array<int, 4>> quads;
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i + 1, b = 2 * i + 2;
    // The strip closes with a half twist: the last quadrangle joins a to b.
    const int next_a = i + 1 < n ? a + 2 : 2, next_b = i + 1 < n ? b + 2 : 1;
    quads.push_back({a, next_a, next_b, b});
  }
  GmshReadOptions reorient;
  reorient.reorient = true;
  const std::string path = write_temp(simple_msh(nodes, quads));
  expect_input_error([&] { read_gmsh_mesh(path, reorient); }, {path, "not orientable"});
}

TEST(GmshReader, RefusesGroupNodesOutsideTheQuadrangles) {
  // The physical point "load" moved to a node that no quadrangle uses.
  std::string text = file_text(kFixture);
  text = replaced(text, "9 9 1 12", "10 10 1 20");
  text = replaced(text, "$EndNodes", "0 3 0 1\n20\n5 5 0\n$EndNodes");
  text = replaced(text, "0 3 15 1\n1 3", "0 3 15 1\n1 20");
  const std::string path = write_temp(text);
  expect_input_error([&] { read(path); },
                     {path, "node 20 of physical group 'load'", "belongs to no quadrangle"});
}

}  // namespace
}  // namespace si
