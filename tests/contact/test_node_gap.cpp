#include "contact/node_gap.hpp"

#include <gtest/gtest.h>

#include "contact/indenter_factory.hpp"

namespace si {
namespace {

struct NodeFixture {
  IndenterPose pose;
  std::unique_ptr<Indenter> indenter;
  NodeContactGeometry geometry{Vector3d(1.5, -0.8, 0.2), 1.9};
  NodeState state;
  NodeFixture() {
    pose.position = Vector3d(0.2, 0.1, 15.0);
    IndenterSpec spec;  // sphere, R = 12.7
    indenter = make_indenter(spec, pose);
    state = reference_node_state(Vector3d(0.1, -0.2, 1.0).normalized());
    state.u = Vector3d(0.05, -0.1, -0.3);
    rotate_node(state, 0.3, -0.25);  // a tilted, turned director
  }
  // The node moved by the increment delta = (du, q) about its current axes.
  NodeState moved(const Vector5d& delta) const {
    NodeState s = state;
    s.u += delta.head<3>();
    rotate_node(s, delta[3], delta[4]);
    return s;
  }
  NodeGap gap(const NodeState& s, bool derivative) const {
    return node_gap(*indenter, pose.direction, geometry, s, 1.0, 0.0, derivative);
  }
};

// G and dG against central differences over increments about the current axes (the element's
// dof convention): G_k = dg/d delta_k, dG_.k = dG/d delta_k with G in the moved node's axes.
TEST(NodeGap, GradientAndDerivativeMatchFiniteDifferences) {
  const NodeFixture f;
  const NodeGap g = f.gap(f.state, true);
  ASSERT_TRUE(g.hits);
  const double h = 1e-6;
  for (int k = 0; k < 5; ++k) {
    Vector5d delta = Vector5d::Zero();
    delta[k] = h;
    const NodeGap p = f.gap(f.moved(delta), false), m = f.gap(f.moved(-delta), false);
    EXPECT_NEAR(g.gradient[k], (p.gap - m.gap) / (2 * h), 1e-8) << "dof " << k;
    const Vector5d fd = (p.gradient - m.gradient) / (2 * h);
    EXPECT_LT((g.gradient_derivative.col(k) - fd).norm(), 1e-7 * (1 + fd.norm())) << "dof " << k;
  }
}

// The gap of the mid-surface node (c = 0) does not depend on the rotations.
TEST(NodeGap, MidSurfaceGapIgnoresRotations) {
  NodeFixture f;
  f.geometry.offset = 0;
  const NodeGap g = f.gap(f.state, true);
  EXPECT_EQ(g.gradient.tail<2>().norm(), 0.0);
  EXPECT_EQ(g.gradient_derivative.bottomRows<2>().norm(), 0.0);
}

// The linearised gap equals the exact one at the reference state, and agrees to second order
// for small chart coordinates.
TEST(NodeGap, LinearizedGapIsTheFirstOrderExpansion) {
  NodeFixture f;
  const NodeState ref = reference_node_state(f.state.d);
  for (double scale : {1e-2, 1e-3}) {
    const Vector5d q = scale * (Vector5d() << 0.3, -0.2, 0.5, 0.4, -0.6).finished();
    NodeState s = ref;
    s.u = q.head<3>();
    rotate_node(s, q[3], q[4]);  // the chart: one rotation from the reference frame
    const NodeGap exact = f.gap(s, false);
    const NodeGap lin = linearized_node_gap(*f.indenter, f.pose.direction, f.geometry, ref, q, 1.0);
    const NodeGap lin0 =
        linearized_node_gap(*f.indenter, f.pose.direction, f.geometry, ref, Vector5d::Zero(), 1.0);
    EXPECT_NEAR(lin0.gap, f.gap(ref, false).gap, 1e-13);
    EXPECT_LT(std::abs(lin.gap - exact.gap), 2.0 * scale * scale) << scale;  // O(|q|^2)
  }
}

}  // namespace
}  // namespace si
