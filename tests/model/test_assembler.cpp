#include "model/assembler.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "model/supports.hpp"
#include "spring_net_element.hpp"
#include "test_meshes.hpp"

namespace si {
namespace {

using testing::SpringNetElement;

// A deformed, rotated state so that every term of the fake element is active.
std::vector<NodeState> wavy_state(const Mesh& m) {
  std::vector<NodeState> s = reference_state(m);
  for (int n = 0; n < m.num_nodes(); ++n) {
    const Vector3d& X = m.nodes[n];
    s[n].u = Vector3d(0.02 * X.y(), -0.01 * X.x(), 0.05 * std::sin(3 * X.x()) * X.y());
    rotate_node(s[n], 0.03 * X.x(), -0.02 * X.y());
  }
  return s;
}

// Dense reference: plain element loop, full matrix, then rows/columns of free dofs.
Eigen::MatrixXd dense_tangent(const Mesh& m, const DofMap& dofs, const ShellElement& el,
                              const std::vector<NodeState>& s, Eigen::VectorXd& force,
                              double& energy) {
  const int N = dofs.num_dofs();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N, N);
  force = Eigen::VectorXd::Zero(N);
  energy = 0;
  for (int e = 0; e < m.num_elements(); ++e) {
    ElementGeometry geo;
    std::array<NodeState, 4> es;
    for (int a = 0; a < 4; ++a) {
      geo.X[a] = m.nodes[m.elements[e][a]];
      geo.D[a] = m.directors[m.elements[e][a]];
      es[a] = s[m.elements[e][a]];
    }
    ElementResponse r;
    el.compute(geo, es, testing::unused_law(), Kinematics::kNonlinear, {}, r);
    const ElementDofs d = DofMap::element_dofs(m.elements[e]);
    for (int i = 0; i < 20; ++i) {
      force[d[i]] += r.force[i];
      for (int j = 0; j < 20; ++j) K(d[i], d[j]) += r.tangent(i, j);
    }
    energy += r.energy;
  }
  Eigen::MatrixXd Kff(dofs.num_free(), dofs.num_free());
  for (int i = 0; i < dofs.num_free(); ++i)
    for (int j = 0; j < dofs.num_free(); ++j)
      Kff(i, j) = K(dofs.free_dofs()[i], dofs.free_dofs()[j]);
  return Kff;
}

TEST(Assembler, EqualsDenseReferenceAssembly) {
  const Mesh m = testing::quarter_cap(5, 4.0, 10.0);
  const DofMap dofs = make_dof_map(m, {{SupportKind::kClamped, "right", -1, {}},
                                       {SupportKind::kSymmetryPlane, "left", 0, {}},
                                       {SupportKind::kSymmetryPlane, "bottom", 1, {}}});
  const SpringNetElement el;
  const Assembler assembler(m, dofs, el, testing::unused_law(), Kinematics::kNonlinear);
  const std::vector<NodeState> s = wavy_state(m);
  Assembly a = assembler.make_assembly();
  assembler.assemble(s, {}, a);
  Eigen::VectorXd force;
  double energy;
  const Eigen::MatrixXd K = dense_tangent(m, dofs, el, s, force, energy);
  const Eigen::MatrixXd Ks = Eigen::MatrixXd(a.tangent);
  EXPECT_LT((Ks - K).norm(), 1e-13 * K.norm()) << (Ks - K).norm() / K.norm();
  EXPECT_LT((a.internal_force - force).norm(), 1e-13 * force.norm());
  EXPECT_NEAR(a.energy, energy, 1e-13 * energy);
  EXPECT_GT(energy, 0.0);
  // The pattern holds exactly the node-adjacency blocks of the free dofs: 5x5 per pair of nodes
  // sharing an element, minus prescribed rows/columns (no element-local zeros dropped).
  EXPECT_GE(a.tangent.nonZeros(), (K.array() != 0.0).count());
  EXPECT_EQ(a.tangent.rows(), dofs.num_free());
  EXPECT_LE(assembler.num_colours(), 4);  // structured quad mesh: 4 colours
}

// Colouring makes the sum order per matrix slot independent of the thread count: bitwise equal.
TEST(Assembler, OpenMpEqualsSerial) {
  const Mesh m = testing::square_plate(12, 9);
  const DofMap dofs = make_dof_map(m, {{SupportKind::kClamped, "left", -1, {}}});
  const SpringNetElement el;
  const std::vector<NodeState> s = wavy_state(m);
  const Assembler serial(m, dofs, el, testing::unused_law(), Kinematics::kNonlinear, 1);
  const Assembler parallel(m, dofs, el, testing::unused_law(), Kinematics::kNonlinear, 2);
  Assembly a1 = serial.make_assembly(), a2 = parallel.make_assembly();
  serial.assemble(s, {}, a1);
  parallel.assemble(s, {}, a2);
  ASSERT_EQ(a1.tangent.nonZeros(), a2.tangent.nonZeros());
  for (Eigen::Index k = 0; k < a1.tangent.nonZeros(); ++k)
    ASSERT_EQ(a1.tangent.valuePtr()[k], a2.tangent.valuePtr()[k]) << k;
  EXPECT_EQ(a1.internal_force, a2.internal_force);
  EXPECT_EQ(a1.energy, a2.energy);
  // Re-assembling into the same Assembly overwrites (no accumulation from the previous call).
  parallel.assemble(s, {}, a2);
  EXPECT_EQ(a1.internal_force, a2.internal_force);
  EXPECT_EQ(a1.tangent.valuePtr()[7], a2.tangent.valuePtr()[7]);
}

// An element that refuses one element's state: the error crosses the OpenMP region intact.
class RefusingElement : public SpringNetElement {
 public:
  void compute(const ElementGeometry& geo, const std::array<NodeState, 4>& nodes,
               const ShellLaw& law, Kinematics kin, const ElementRequest& req,
               ElementResponse& out) const override {
    if (geo.X[0].norm() == 0.0) throw_numerical("element 0 is inverted");
    SpringNetElement::compute(geo, nodes, law, kin, req, out);
  }
};

TEST(Assembler, ElementErrorsLeaveTheParallelRegion) {
  const Mesh m = testing::square_plate(6, 6);
  const DofMap dofs = make_dof_map(m, {{SupportKind::kClamped, "left", -1, {}}});
  const RefusingElement el;
  for (int threads : {1, 2}) {
    const Assembler a(m, dofs, el, testing::unused_law(), Kinematics::kNonlinear, threads);
    Assembly out = a.make_assembly();
    try {
      a.assemble(reference_state(m), {}, out);
      ADD_FAILURE() << "no error with " << threads << " threads";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
      EXPECT_EQ(e.reason(), "element 0 is inverted");
    }
  }
}

TEST(Assembler, ReactionsAreInternalMinusExternalAtPrescribedDofs) {
  const DofMap dofs(2, {{3, 0.0}, {7, 0.0}});
  Eigen::VectorXd fi = Eigen::VectorXd::LinSpaced(10, 1, 10), fe = Eigen::VectorXd::Ones(10);
  const Eigen::VectorXd r = reactions(dofs, fi, fe);
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(10);
  expected[3] = 3.0;
  expected[7] = 7.0;
  EXPECT_EQ(r, expected);
}

}  // namespace
}  // namespace si
