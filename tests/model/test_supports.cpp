#include "model/supports.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <set>

#include "core/error.hpp"
#include "test_meshes.hpp"

namespace si {
namespace {

using testing::quarter_cap;
using testing::square_plate;

// The local dofs (0..4) prescribed at `node`.
std::set<int> fixed_at(const DofMap& map, int node) {
  std::set<int> s;
  for (int l = 0; l < 5; ++l)
    if (map.is_prescribed(DofMap::dof(node, l))) s.insert(l);
  return s;
}

std::string error_text(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    return e.what();
  }
  ADD_FAILURE() << "no error thrown";
  return "";
}

TEST(Supports, ClampedHingedFixedDofsConstrainTheirDofs) {
  const Mesh m = square_plate(2, 2);
  const DofMap clamped = make_dof_map(m, {{SupportKind::kClamped, "left", -1, {}}});
  for (int n : m.node_sets.at("left"))
    EXPECT_EQ(fixed_at(clamped, n), (std::set<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(clamped.num_prescribed(), 15);
  const DofMap hinged = make_dof_map(m, {{SupportKind::kHinged, "left", -1, {}}});
  for (int n : m.node_sets.at("left")) EXPECT_EQ(fixed_at(hinged, n), (std::set<int>{0, 1, 2}));
  EXPECT_EQ(hinged.num_prescribed(), 9);
  const DofMap fixed = make_dof_map(m, {{SupportKind::kFixedDofs, "corner", -1, {1, 4}}});
  EXPECT_EQ(fixed_at(fixed, 0), (std::set<int>{1, 4}));
  EXPECT_EQ(fixed.num_prescribed(), 2);
}

TEST(Supports, SimplySupportedFixesTheDeflectionAlongAnAxisDirector) {
  Mesh m = square_plate(2, 2);
  const DofMap ss = make_dof_map(m, {{SupportKind::kSimplySupported, "left", -1, {}}});
  for (int n : m.node_sets.at("left")) EXPECT_EQ(fixed_at(ss, n), (std::set<int>{2}));
  // A plate in the y-z plane: the deflection is u1.
  for (auto& D : m.directors) D = -Vector3d::UnitX();
  const DofMap ssx = make_dof_map(m, {{SupportKind::kSimplySupported, "left", -1, {}}});
  for (int n : m.node_sets.at("left")) EXPECT_EQ(fixed_at(ssx, n), (std::set<int>{0}));
  // A tilted director is refused with an explanation.
  m.directors[0] = Vector3d(0.1, 0, 1).normalized();
  const std::string msg = error_text([&] {
    make_dof_map(m, {{SupportKind::kSimplySupported, "left", -1, {}}});
  });
  EXPECT_NE(msg.find("not within 1e-8 of a global axis"), std::string::npos) << msg;
  EXPECT_NE(msg.find("node 0"), std::string::npos) << msg;
}

// Flat plate, D = e3: v1 = e1, v2 = e2. On x = 0 the rotation about v2 (moves d along e1) is fixed,
// on y = 0 the rotation about v1 (moves d along -e2).
TEST(Supports, SymmetryPlanesOfAFlatPlate) {
  const Mesh m = square_plate(3, 3);
  const DofMap map = make_dof_map(m, {{SupportKind::kSymmetryPlane, "left", 0, {}},
                                      {SupportKind::kSymmetryPlane, "bottom", 1, {}}});
  for (int n : m.node_sets.at("left")) {
    if (n == 0) continue;
    EXPECT_EQ(fixed_at(map, n), (std::set<int>{0, 4})) << n;
  }
  for (int n : m.node_sets.at("bottom")) {
    if (n == 0) continue;
    EXPECT_EQ(fixed_at(map, n), (std::set<int>{1, 3})) << n;
  }
  EXPECT_EQ(fixed_at(map, 0), (std::set<int>{0, 1, 3, 4}));
}

// Quarter spherical cap with radial directors. On x = 0: D = (0, Dy, Dz), v1 = e1 and v1 x D =
// -v2 lies in the plane, v2 x D = v1 = e1: fix the rotation about v2. On y = 0: v2 = e2 and
// v1 x D = -v2 = -e2: fix the rotation about v1.
TEST(Supports, SymmetryPlanesOfASphericalCap) {
  const Mesh m = quarter_cap(4, 3.0, 10.0);
  const DofMap map = make_dof_map(m, {{SupportKind::kSymmetryPlane, "left", 0, {}},
                                      {SupportKind::kSymmetryPlane, "bottom", 1, {}}});
  for (int n : m.node_sets.at("left")) {
    if (n == 0) continue;
    const NodeState f = reference_node_state(m.directors[n]);
    EXPECT_NEAR(f.v1.x(), 1.0, 1e-14);
    EXPECT_EQ(fixed_at(map, n), (std::set<int>{0, 4})) << n;
  }
  for (int n : m.node_sets.at("bottom")) {
    if (n == 0) continue;
    const NodeState f = reference_node_state(m.directors[n]);
    EXPECT_NEAR(f.v2.y(), 1.0, 1e-14);
    EXPECT_EQ(fixed_at(map, n), (std::set<int>{1, 3})) << n;
  }
}

// With the reference frame v1 = (e2 x D)/|e2 x D|, a director lying in a coordinate plane always
// has v1 or v2 along that plane's normal (v1 = +-e1 for D in x = 0, v2 = +-e2 for D in y = 0,
// v1 = +-e3 for D in z = 0), so the "frame not aligned" error can only fire with another frame
// convention; what a user meets is a director that is not in the plane.
TEST(Supports, SymmetryPlaneNeedsTheDirectorInThePlane) {
  Mesh m = square_plate(2, 2);
  for (auto& D : m.directors) D = Vector3d(1, 1, 0).normalized();  // in the plane z = 0
  const DofMap ok = make_dof_map(m, {{SupportKind::kSymmetryPlane, "left", 2, {}}});
  for (int n : m.node_sets.at("left")) EXPECT_EQ(fixed_at(ok, n), (std::set<int>{2, 4}));
  for (auto& D : m.directors) D = Vector3d(1, 0, 1).normalized();  // not in the plane x = 0
  const std::string msg = error_text([&] {
    make_dof_map(m, {{SupportKind::kSymmetryPlane, "left", 0, {}}});
  });
  EXPECT_NE(msg.find("is not in the symmetry plane"), std::string::npos) << msg;
}

TEST(Supports, PrescribedDisplacementsAndConflicts) {
  const Mesh m = square_plate(2, 2);
  const DofMap map =
      make_dof_map(m, {{SupportKind::kHinged, "left", -1, {}}}, {{"right", 2, -0.25}});
  for (int n : m.node_sets.at("right")) {
    EXPECT_EQ(fixed_at(map, n), (std::set<int>{2}));
    EXPECT_DOUBLE_EQ(map.prescribed_value(DofMap::dof(n, 2)), -0.25);
  }
  // u3 of the corner is clamped to 0 and prescribed to 1: refused.
  EXPECT_THROW(make_dof_map(m, {{SupportKind::kClamped, "left", -1, {}}}, {{"corner", 2, 1.0}}),
               Error);
  EXPECT_THROW(make_dof_map(m, {}, {{"corner", 3, 1.0}}), Error);  // rotation: not a component
}

TEST(Supports, UnknownNodeSetListsTheAvailableSets) {
  const Mesh m = square_plate(1, 1);
  const std::string msg = error_text([&] {
    make_dof_map(m, {{SupportKind::kClamped, "edge", -1, {}}});
  });
  EXPECT_NE(msg.find("unknown node set 'edge'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("available node sets: all, bottom, corner, far_corner, left, right, top"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("support 0"), std::string::npos) << msg;
}

TEST(Supports, RefusesBadAxisAndDofs) {
  const Mesh m = square_plate(1, 1);
  EXPECT_THROW(make_dof_map(m, {{SupportKind::kSymmetryPlane, "left", 3, {}}}), Error);
  EXPECT_THROW(make_dof_map(m, {{SupportKind::kFixedDofs, "left", -1, {5}}}), Error);
  EXPECT_THROW(make_dof_map(m, {{SupportKind::kFixedDofs, "left", -1, {}}}), Error);
}

}  // namespace
}  // namespace si
