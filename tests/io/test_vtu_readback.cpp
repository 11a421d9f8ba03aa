// The VTU files read back by an independent reader, meshio (python3-meshio, through
// tests/io/vtu_to_json.py): a converged nonlinear state of Sze's quarter roof written as ascii,
// as appended raw binary and mirrored into the whole roof. The reference is our own state: the
// reference points plus the displacement field must give X + u of every node (what ParaView's
// Warp By Vector shows), binary must carry the same numbers as ascii, and the mirror must have
// the point count of the full shape and the symmetry of the state.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "../verification/sze_roof_support.hpp"
#include "analysis/static_run.hpp"
#include "io/result_fields.hpp"
#include "io/vtu_writer.hpp"
#include "model/assembler.hpp"
#include "test_paths.hpp"

namespace si {
namespace {

namespace fs = std::filesystem;

// meshio's reading of `file` (see vtu_to_json.py); a failed read fails the test.
nlohmann::json read_with_meshio(const fs::path& file) {
  const std::string cmd = "/usr/bin/python3 '" + std::string(SHELLINDENT_SOURCE_DIR) +
                          "/tests/io/vtu_to_json.py' '" + file.string() + "' 2>&1";
  std::string text;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (pipe == nullptr) return {};
  char buf[4096];
  std::size_t n = 0;
  while ((n = fread(buf, 1, sizeof buf, pipe)) > 0) text.append(buf, n);
  const int status = pclose(pipe);
  EXPECT_EQ(status, 0) << "meshio could not read " << file << " (is python3-meshio installed? "
                       << "scripts/setup.sh): " << text;
  return status == 0 ? nlohmann::json::parse(text) : nlohmann::json{};
}

// The quarter roof (h = 12.7) at half the snap-through load, 3 natural steps: rotations and
// displacements of several mm, a state with membrane and bending fields.
struct RoofState {
  verification::SzeRoof roof = verification::make_sze_roof(12.7, 4);
  std::vector<NodeState> state;
  VtuFields fields;
};

RoofState solved_roof() {
  RoofState r;
  for (PointLoad& p : r.roof.loads.points) p.force *= 0.5;
  const DofMap dofs = make_dof_map(r.roof.mesh, r.roof.supports);
  StaticSettings settings;
  settings.steps = 3;
  settings.record_nodes = {0};
  const StaticResult result = run_static(r.roof.mesh, dofs, *r.roof.element, r.roof.law,
                                         Kinematics::kNonlinear, r.roof.loads, settings, {}, 1);
  EXPECT_EQ(result.failure, "");
  r.state = result.state;
  const Assembler assembler(r.roof.mesh, dofs, *r.roof.element, r.roof.law, Kinematics::kNonlinear,
                            1);
  r.fields = resultant_fields(r.roof.mesh, assembler, *r.roof.element, r.roof.law, r.state);
  r.fields.cell_data["element_index"] =
      Eigen::VectorXd::LinSpaced(r.roof.mesh.num_elements(), 0, r.roof.mesh.num_elements() - 1);
  return r;
}

fs::path scratch() {
  const fs::path dir = fs::temp_directory_path() / ("si_vtu_readback_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

Vector3d row3(const nlohmann::json& rows, std::size_t i) {
  return Vector3d(rows[i][0].get<double>(), rows[i][1].get<double>(), rows[i][2].get<double>());
}

TEST(VtuReadback, ReferencePointsPlusDisplacementAreTheDeformedNodes_Meshio) {
  const RoofState r = solved_roof();
  const Mesh& mesh = r.roof.mesh;
  const fs::path dir = scratch();
  double largest_u = 0;
  for (const NodeState& s : r.state) largest_u = std::max(largest_u, s.u.norm());
  ASSERT_GT(largest_u, 1.0) << "the state should be visibly deformed (mm)";
  for (VtuEncoding encoding : {VtuEncoding::kAscii, VtuEncoding::kBinary}) {
    const fs::path file = dir / "roof.vtu";
    write_vtu(file.string(), mesh, r.state, r.fields, {encoding, false});
    const nlohmann::json g = read_with_meshio(file);
    ASSERT_FALSE(g.is_null());
    ASSERT_EQ(g.at("points").size(), static_cast<std::size_t>(mesh.num_nodes()));
    ASSERT_EQ(g.at("quads").size(), static_cast<std::size_t>(mesh.num_elements()));
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const Vector3d X = row3(g.at("points"), n);
      const Vector3d u = row3(g.at("point_data").at("displacement"), n);
      // Ascii writes 17 significant digits and binary the bits: both exact.
      EXPECT_EQ(X, mesh.nodes[n]) << "node " << n;
      EXPECT_EQ(X + u, mesh.nodes[n] + r.state[n].u) << "node " << n;
      EXPECT_EQ(row3(g.at("point_data").at("director"), n), r.state[n].d) << "node " << n;
    }
    for (int e = 0; e < mesh.num_elements(); ++e)
      for (int k = 0; k < 4; ++k) EXPECT_EQ(g.at("quads")[e][k].get<int>(), mesh.elements[e][k]);
  }
  fs::remove_all(dir);
}

TEST(VtuReadback, BinaryAndAsciiCarryTheSameArrays_Meshio) {
  const RoofState r = solved_roof();
  const fs::path dir = scratch();
  write_vtu((dir / "a.vtu").string(), r.roof.mesh, r.state, r.fields, {VtuEncoding::kAscii});
  write_vtu((dir / "b.vtu").string(), r.roof.mesh, r.state, r.fields, {VtuEncoding::kBinary});
  const nlohmann::json a = read_with_meshio(dir / "a.vtu");
  const nlohmann::json b = read_with_meshio(dir / "b.vtu");
  ASSERT_FALSE(a.is_null() || b.is_null());
  EXPECT_EQ(a.at("point_data").size(), r.fields.point_data.size() + 2);  // + displacement, director
  EXPECT_EQ(a.at("cell_data").size(), 1u);
  EXPECT_EQ(a, b);  // every number the same
  // The binary file is the smaller one (the arrays of this small mesh: about a third).
  EXPECT_LT(fs::file_size(dir / "b.vtu"), fs::file_size(dir / "a.vtu") / 2);
  fs::remove_all(dir);
}

// The full roof from the quarter: 4 N - 2 (nodes on x = 0) - 2 (on y = 0) + (on both) points,
// 4 times the cells, each quarter's image with the state mirrored (vectors: the mirrored axis
// flips; N, M: the 12 column; Q1 under x -> -x, Q2 under y -> -y), cells facing the directors.
TEST(VtuReadback, MirroredQuarterIsTheFullShapeWithTheMirroredState_Meshio) {
  const RoofState r = solved_roof();
  const Mesh& mesh = r.roof.mesh;
  const fs::path dir = scratch();
  write_vtu((dir / "full.vtu").string(), mesh, r.state, r.fields, {VtuEncoding::kBinary, true});
  const nlohmann::json g = read_with_meshio(dir / "full.vtu");
  ASSERT_FALSE(g.is_null());
  int on_x = 0, on_y = 0, on_both = 0;
  for (const Vector3d& X : mesh.nodes) {
    on_x += X.x() == 0;
    on_y += X.y() == 0;
    on_both += X.x() == 0 && X.y() == 0;
  }
  ASSERT_GT(on_x, 0);
  ASSERT_GT(on_y, 0);
  const auto& points = g.at("points");
  EXPECT_EQ(points.size(),
            static_cast<std::size_t>(4 * mesh.num_nodes() - 2 * on_x - 2 * on_y + on_both));
  EXPECT_EQ(g.at("quads").size(), static_cast<std::size_t>(4 * mesh.num_elements()));
  const auto& pd = g.at("point_data");
  // Every point of the full roof is the image of a quarter node under (sx, sy) = (+-1, +-1).
  std::size_t matched = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Vector3d X = row3(points, p);
    const double sx = X.x() < 0 ? -1 : 1, sy = X.y() < 0 ? -1 : 1;
    const Vector3d Xq(sx * X.x(), sy * X.y(), X.z());
    int n = -1;
    for (int k = 0; k < mesh.num_nodes() && n < 0; ++k)
      if ((mesh.nodes[k] - Xq).norm() < 1e-9) n = k;
    ASSERT_GE(n, 0) << "point " << p << " is no image of a quarter node";
    ++matched;
    const Vector3d u = r.state[n].u;
    EXPECT_EQ(row3(pd.at("displacement"), p), Vector3d(sx * u.x(), sy * u.y(), u.z()));
    const Eigen::MatrixXd& N = r.fields.point_data.at("N");
    EXPECT_EQ(pd.at("N")[p][0].get<double>(), N(n, 0));
    EXPECT_EQ(pd.at("N")[p][1].get<double>(), sx * sy * N(n, 1));
    EXPECT_EQ(pd.at("Q1")[p][0].get<double>(), sx * r.fields.point_data.at("Q1")(n, 0));
    EXPECT_EQ(pd.at("Q2")[p][0].get<double>(), sy * r.fields.point_data.at("Q2")(n, 0));
  }
  EXPECT_EQ(matched, points.size());
  // Each cell's normal (diagonals' cross product) on the side of its nodes' directors.
  for (const auto& q : g.at("quads")) {
    const Vector3d a = row3(points, q[0]), b = row3(points, q[1]), c = row3(points, q[2]),
                   d = row3(points, q[3]);
    Vector3d director = Vector3d::Zero();
    for (int k = 0; k < 4; ++k) director += row3(pd.at("director"), q[k]);
    EXPECT_GT((c - a).cross(d - b).dot(director), 0);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace si
