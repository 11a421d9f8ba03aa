#include "model/loads.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "analysis/static_run.hpp"
#include "core/error.hpp"
#include "model/assembler.hpp"
#include "model/dof_map.hpp"
#include "model/supports.hpp"
#include "test_meshes.hpp"

namespace si {
namespace {

using testing::square_plate;

Vector3d total_force(const Eigen::VectorXd& f) {
  Vector3d s = Vector3d::Zero();
  for (Eigen::Index n = 0; n < f.size() / 5; ++n) s += f.segment<3>(5 * n);
  return s;
}

TEST(Loads, PointLoadsSplitOrPerNode) {
  const Mesh m = square_plate(2, 2);
  Loads loads;
  loads.points.push_back({"right", Vector3d(0, 0, -3.0), false});
  loads.points.push_back({"corner", Vector3d(1.0, 0, 0), true});
  const Eigen::VectorXd f = fixed_load_vector(m, loads);
  for (int n : m.node_sets.at("right")) EXPECT_DOUBLE_EQ(f[DofMap::dof(n, 2)], -1.0);
  EXPECT_DOUBLE_EQ(f[DofMap::dof(0, 0)], 1.0);
  EXPECT_TRUE(total_force(f).isApprox(Vector3d(1, 0, -3), 1e-15));
  Loads each;
  each.points.push_back({"right", Vector3d(0, 0, -3.0), true});
  EXPECT_NEAR(total_force(fixed_load_vector(m, each)).z(), -9.0, 1e-14);
}

TEST(Loads, LineLoadIsConsistentOnSegments) {
  const Mesh m = square_plate(4, 1, 2.0, 1.0);  // bottom edge nodes 0..4, segments of 0.5
  Loads loads;
  loads.lines.push_back({{0, 1, 2, 3, 4}, Vector3d(0, 0, 2.0)});
  const Eigen::VectorXd f = fixed_load_vector(m, loads);
  EXPECT_DOUBLE_EQ(f[DofMap::dof(0, 2)], 0.5);  // q L / 2 at the ends
  EXPECT_DOUBLE_EQ(f[DofMap::dof(2, 2)], 1.0);  // q L inside
  EXPECT_DOUBLE_EQ(f[DofMap::dof(4, 2)], 0.5);
  EXPECT_DOUBLE_EQ(total_force(f).z(), 4.0);  // q * length
  Loads bad;
  bad.lines.push_back({{0}, Vector3d(0, 0, 1)});
  EXPECT_THROW(fixed_load_vector(m, bad), Error);
  bad.lines[0].edge_nodes = {0, 0};
  EXPECT_THROW(fixed_load_vector(m, bad), Error);
}

// A flat 3 x 2 rectangle meshed 3 x 4 (irregularly shifted interior nodes): sum of the consistent
// nodal forces = p A n exactly, in the director's direction.
TEST(Loads, DeadPressureOnAFlatPlateGivesPTimesArea) {
  Mesh m = square_plate(3, 4, 3.0, 2.0);
  m.nodes[6] += Vector3d(0.1, -0.07, 0);  // interior node: quads no longer parallelograms
  Loads loads;
  loads.pressures.push_back({0.7, false, {}});
  const Vector3d F = total_force(fixed_load_vector(m, loads));
  EXPECT_NEAR(F.z(), 0.7 * 6.0, 1e-14);
  EXPECT_NEAR(F.x(), 0.0, 1e-15);
  EXPECT_NEAR(F.y(), 0.0, 1e-15);
  // The follower pressure at the reference state is the same load.
  loads.pressures[0].follower = true;
  EXPECT_NEAR(total_force(follower_load_vector(m, loads, reference_state(m))).z(), 4.2, 1e-14);
  EXPECT_EQ(total_force(fixed_load_vector(m, loads)).norm(), 0.0);
}

// The load stiffness is the derivative of the follower nodal forces with respect to the nodal
// positions: central differences on a warped, stretched element (non-symmetric stiffness).
TEST(Loads, FollowerPressureStiffnessMatchesFiniteDifferences) {
  const std::array<Vector3d, 4> x = {Vector3d(0, 0, 0.1), Vector3d(1.2, 0.1, -0.2),
                                     Vector3d(1.0, 0.9, 0.3), Vector3d(-0.1, 1.1, 0.0)};
  const double p = 1.7;
  const Eigen::Matrix<double, 12, 12> K = pressure_load_stiffness(x, p);
  Eigen::Matrix<double, 12, 12> fd;
  const double h = 1e-6;
  for (int j = 0; j < 12; ++j) {
    std::array<Vector3d, 4> xp = x, xm = x;
    xp[j / 3][j % 3] += h;
    xm[j / 3][j % 3] -= h;
    fd.col(j) = (pressure_nodal_forces(xp, p) - pressure_nodal_forces(xm, p)) / (2 * h);
  }
  EXPECT_LT((K - fd).norm() / K.norm(), 1e-6) << (K - fd).norm() / K.norm();
  EXPECT_GT((K - K.transpose()).norm(), 1e-3 * K.norm());  // genuinely non-symmetric
}

// Same check at the global level through for_each_follower_stiffness and the state.
TEST(Loads, GlobalFollowerStiffnessMatchesFiniteDifferences) {
  const Mesh m = square_plate(2, 2);
  std::vector<NodeState> state = reference_state(m);
  for (int n = 0; n < m.num_nodes(); ++n)
    state[n].u = Vector3d(0.05 * std::sin(n), 0.03 * std::cos(2 * n), 0.1 * std::sin(3 * n));
  Loads loads;
  loads.pressures.push_back({2.0, true, {0, 3}});
  const int N = 5 * m.num_nodes();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
  for_each_follower_stiffness(m, loads, state, [&](int e, const Eigen::Matrix<double, 20, 20>& b) {
    const ElementDofs d = DofMap::element_dofs(m.elements[e]);
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < 20; ++j) K(d[i], d[j]) += b(i, j);
  });
  Eigen::MatrixXd fd = Eigen::MatrixXd::Zero(N, N);
  const double h = 1e-6;
  for (int j = 0; j < N; ++j) {
    if (j % 5 >= 3) continue;  // pressure does not depend on the rotations
    std::vector<NodeState> sp = state, sm = state;
    sp[j / 5].u[j % 5] += h;
    sm[j / 5].u[j % 5] -= h;
    fd.col(j) = (follower_load_vector(m, loads, sp) - follower_load_vector(m, loads, sm)) / (2 * h);
  }
  EXPECT_LT((K - fd).norm() / K.norm(), 1e-6);
}

// Generalised forces M . V1, M . V2 on the rotation dofs, with the node's reference axes
// (director.hpp): V1 = e1, V2 = e2 for D = e3; for D = (0, 1, 1)/sqrt 2, V1 = e1 and
// V2 = (0, 1, -1)/sqrt 2.
TEST(Loads, NodalMomentActsOnTheReferenceRotationAxes) {
  Mesh m = square_plate(1, 1);  // "right" = nodes 1 and 3
  Loads loads;
  loads.moments.push_back({"right", Vector3d(1.0, 2.0, 0), false});  // total, split in two
  Eigen::VectorXd f = fixed_load_vector(m, loads);
  for (int n : m.node_sets.at("right")) {
    EXPECT_DOUBLE_EQ(f[DofMap::dof(n, 3)], 0.5);
    EXPECT_DOUBLE_EQ(f[DofMap::dof(n, 4)], 1.0);
  }
  EXPECT_EQ(total_force(f).norm(), 0.0);  // no force on the translations
  EXPECT_DOUBLE_EQ(f.cwiseAbs().sum(), 3.0);
  m.directors[3] = Vector3d(0, 1, 1).normalized();  // the far corner
  Loads tilted;
  tilted.moments.push_back({"far_corner", Vector3d(0, 1, -1), true});
  f = fixed_load_vector(m, tilted);
  EXPECT_NEAR(f[DofMap::dof(3, 3)], 0.0, 1e-15);
  EXPECT_NEAR(f[DofMap::dof(3, 4)], std::sqrt(2.0), 1e-15);
}

// The generalised forces are work-conjugate to the rotation dofs: a linear cantilever strip (nu =
// 0, EI = E b t^3 / 12) under an end moment M about -e2 bends uniformly, tip deflection M L^2 /
// (2 EI) and tip rotation M L / EI, exact for mitc4 (pure bending). Linear mode stores the
// linearised director D + theta (V2 x D) = (-theta, 0, 1) at the tip (load_problem.hpp).
TEST(Loads, NodalMomentBendsALinearCantileverUniformly) {
  const double L = 4, b = 1, t = 0.1, E = 1e4, M = 0.02;
  const double EI = E * b * t * t * t / 12;
  const Mesh m = square_plate(4, 1, L, b);
  const DofMap dofs = make_dof_map(m, {{SupportKind::kClamped, "left", -1, {}}});
  const auto element = make_shell_element(ElementType::kMitc4);
  Loads loads;
  loads.moments.push_back({"right", Vector3d(0, -M, 0), false});
  StaticSettings settings;
  settings.steps = 1;
  settings.record_nodes = m.node_sets.at("right");
  const StaticResult run = run_static(m, dofs, *element, isotropic_shell_law(E, 0.0, t),
                                      Kinematics::kLinear, loads, settings);
  ASSERT_EQ(run.steps.size(), 1u) << run.failure;
  const StepResult& r = run.steps.back();
  const std::vector<NodeState>& state = run.state;
  for (std::size_t i = 0; i < r.displacements.size(); ++i) {
    EXPECT_NEAR(r.displacements[i].z(), M * L * L / (2 * EI), 1e-9 * M * L * L / EI);
    const int n = m.node_sets.at("right")[i];
    // Linear mode stores the small rotation as an exact rotation of the director
    // (shell_element.hpp), so the end slope is asin of the director's x component.
    EXPECT_NEAR(std::asin(-state[n].d.x()), M * L / EI, 1e-9 * M * L / EI);
  }
}

TEST(Loads, RefusesBadNodalMoments) {
  const Mesh m = square_plate(1, 1);
  Loads drilling;
  drilling.moments.push_back({"right", Vector3d(0.5, 0, 1e-3), false});
  try {
    fixed_load_vector(m, drilling);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nodal moment 0: the moment has a component along the "
                                         "director of node 1 (drilling)"),
              std::string::npos)
        << e.what();
  }
  Loads unknown;
  unknown.moments.push_back({"tip", Vector3d(1, 0, 0), false});
  EXPECT_THROW(fixed_load_vector(m, unknown), Error);
  Loads nan;
  nan.moments.push_back({"right", Vector3d(std::nan(""), 0, 0), false});
  EXPECT_THROW(fixed_load_vector(m, nan), Error);
}

TEST(Loads, RefusesBadReferences) {
  const Mesh m = square_plate(1, 1);
  Loads loads;
  loads.points.push_back({"apex", Vector3d(0, 0, 1), false});
  try {
    fixed_load_vector(m, loads);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("point load 0: unknown node set 'apex' (available node "
                                         "sets: all, bottom, corner, far_corner, left, right, "
                                         "top)"),
              std::string::npos)
        << e.what();
  }
  Loads bad;
  bad.pressures.push_back({1.0, false, {1}});
  EXPECT_THROW(fixed_load_vector(m, bad), Error);
}

}  // namespace
}  // namespace si
