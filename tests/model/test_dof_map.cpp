#include "model/dof_map.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace si {
namespace {

TEST(DofMap, NumbersNodeMajorAndFreeDofsInOrder) {
  // 3 nodes, node 1 fully clamped, u3 of node 2 prescribed to 0.5.
  std::vector<PrescribedDof> p;
  for (int i = 0; i < 5; ++i) p.push_back({DofMap::dof(1, i), 0.0});
  p.push_back({DofMap::dof(2, 2), 0.5});
  const DofMap map(3, p);
  EXPECT_EQ(map.num_dofs(), 15);
  EXPECT_EQ(map.num_free(), 9);
  EXPECT_EQ(map.num_prescribed(), 6);
  EXPECT_EQ(DofMap::dof(2, 3), 13);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(map.equation(i), i);
  for (int i = 5; i < 10; ++i) EXPECT_EQ(map.equation(i), -1);
  EXPECT_EQ(map.equation(10), 5);
  EXPECT_EQ(map.equation(11), 6);
  EXPECT_EQ(map.equation(12), -1);
  EXPECT_EQ(map.equation(13), 7);
  EXPECT_EQ(map.equation(14), 8);
  EXPECT_DOUBLE_EQ(map.prescribed_value(12), 0.5);
  EXPECT_EQ(map.prescribed_dofs(), (std::vector<int>{5, 6, 7, 8, 9, 12}));
  for (int e = 0; e < map.num_free(); ++e) EXPECT_EQ(map.equation(map.free_dofs()[e]), e);
}

TEST(DofMap, ExpandAndRestrictRoundTrip) {
  const DofMap map(2, {{DofMap::dof(0, 1), 2.0}, {DofMap::dof(1, 4), 0.0}});
  Eigen::VectorXd free(8);
  free << 1, 2, 3, 4, 5, 6, 7, 8;
  const Eigen::VectorXd full = map.expand(free, 0.5);
  Eigen::VectorXd expected(10);
  expected << 1, 1.0 /* 0.5 * 2 */, 2, 3, 4, 5, 6, 7, 8, 0;
  EXPECT_EQ(full, expected);
  EXPECT_EQ(map.restrict_to_free(full), free);
}

TEST(DofMap, GatherScatterUsesTwentyNodeMajorDofs) {
  const std::array<int, 4> nodes = {3, 0, 2, 1};
  const ElementDofs d = DofMap::element_dofs(nodes);
  EXPECT_EQ(d[0], 15);
  EXPECT_EQ(d[4], 19);
  EXPECT_EQ(d[5], 0);
  EXPECT_EQ(d[19], 9);
  Eigen::VectorXd full(20);
  for (int i = 0; i < 20; ++i) full[i] = 100 + i;
  const Eigen::Matrix<double, 20, 1> local = DofMap::gather(d, full);
  for (int i = 0; i < 20; ++i) EXPECT_EQ(local[i], full[d[i]]);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(20);
  DofMap::scatter_add(d, local, sum);
  DofMap::scatter_add(d, local, sum);
  EXPECT_EQ(sum, 2 * full);
}

TEST(DofMap, AcceptsRepeatedEqualValuesRefusesConflicts) {
  EXPECT_NO_THROW(DofMap(2, {{3, 0.0}, {3, 0.0}}));
  try {
    DofMap(2, {{3, 0.0}, {3, 1.0}});
    FAIL() << "conflicting prescribed values accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_NE(std::string(e.what()).find("node 0 dof 3 (rotation v1)"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(DofMap(2, {{10, 0.0}}), Error);
  EXPECT_THROW(DofMap(2, {{-1, 0.0}}), Error);
}

}  // namespace
}  // namespace si
