#include "model/shell_chart.hpp"

#include <gtest/gtest.h>

#include <random>

#include "model/assembler.hpp"
#include "model/supports.hpp"
#include "shell/shell_element.hpp"
#include "test_meshes.hpp"

namespace si {
namespace {

struct ChartFixture {
  Mesh mesh = testing::quarter_cap(3, 6.0, 20.0);
  DofMap dofs = make_dof_map(mesh, {{SupportKind::kClamped, "left", -1, {}}});
  std::unique_ptr<ShellElement> element = make_shell_element(ElementType::kMitc4);
  Assembler assembler{
      mesh, dofs, *element, isotropic_shell_law(7e4, 0.3, 0.5), Kinematics::kNonlinear, 1};
  ShellChart chart{mesh, dofs};

  // A far-from-equilibrium point: translations ~0.2 mm, rotations up to ~0.6 rad.
  Eigen::VectorXd random_point(unsigned seed) const {
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> uni(-1, 1);
    Eigen::VectorXd x(dofs.num_free());
    for (int eq = 0; eq < dofs.num_free(); ++eq)
      x[eq] = (dofs.free_dofs()[eq] % kShellNodeDofs < 3 ? 0.2 : 0.4) * uni(gen);
    return x;
  }
  Eigen::VectorXd residual(const Eigen::VectorXd& x) const {
    std::vector<NodeState> s;
    chart.states(x, 1.0, s);
    Assembly a = assembler.make_assembly();
    assembler.assemble(s, {true, false}, a);
    return dofs.restrict_to_free(a.internal_force);
  }
};

TEST(ShellChart, CoordinatesInvertStates) {
  const ChartFixture f;
  const Eigen::VectorXd x = f.random_point(1);
  std::vector<NodeState> s;
  f.chart.states(x, 1.0, s);
  EXPECT_LT((f.chart.coordinates(s) - x).cwiseAbs().maxCoeff(), 1e-14);
}

// The element's linear mode reads a node set by ONE rotate_node from the reference frame
// (shell_element.hpp); the chart must give the same frame.
TEST(ShellChart, StatesMatchOneRotateNodeFromReference) {
  const ChartFixture f;
  const Eigen::VectorXd x = f.random_point(2);
  std::vector<NodeState> s;
  f.chart.states(x, 1.0, s);
  const std::vector<NodeState> ref = reference_state(f.mesh);
  for (int n = 0; n < f.mesh.num_nodes(); ++n) {
    const int ea = f.dofs.equation(DofMap::dof(n, 3)), eb = f.dofs.equation(DofMap::dof(n, 4));
    NodeState expected = ref[n];
    rotate_node(expected, ea >= 0 ? x[ea] : 0.0, eb >= 0 ? x[eb] : 0.0);
    EXPECT_LT((s[n].d - expected.d).norm(), 1e-14);
    EXPECT_LT((s[n].v1 - expected.v1).norm(), 1e-14);
  }
}

// dr/dx = K T + D against central differences of the residual in chart coordinates, away from
// equilibrium (so the drilling term D matters) and at large rotations (so T differs from I).
TEST(ShellChart, ChartJacobianMatchesFiniteDifferences) {
  const ChartFixture f;
  const Eigen::VectorXd x = f.random_point(3);
  std::vector<NodeState> s;
  f.chart.states(x, 1.0, s);
  Assembly a = f.assembler.make_assembly();
  f.assembler.assemble(s, {true, true}, a);
  const Eigen::VectorXd r = f.dofs.restrict_to_free(a.internal_force);
  SparseMatrix J = a.tangent;
  f.chart.to_chart_jacobian(x, r, J);
  const Eigen::MatrixXd Jd(J);

  const double h = 1e-6;
  Eigen::MatrixXd fd(x.size(), x.size());
  for (int j = 0; j < x.size(); ++j) {
    Eigen::VectorXd xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    fd.col(j) = (f.residual(xp) - f.residual(xm)) / (2 * h);
  }
  // Central differences: error ~ h^2 |r'''| ~ 1e-12 relative; roundoff eps |r| / h ~ 1e-10.
  const double scale = fd.cwiseAbs().maxCoeff();
  EXPECT_LT((Jd - fd).cwiseAbs().maxCoeff() / scale, 1e-7);
  // Without T and D the error is first order in the rotations: the test can fail.
  const Eigen::MatrixXd K(a.tangent);
  EXPECT_GT((K - fd).cwiseAbs().maxCoeff() / scale, 1e-3);
}

TEST(ShellChart, LeftJacobianIsTheDerivativeOfExp) {
  const Vector3d theta(0.7, -0.4, 1.1), dtheta(1e-7, -2e-7, 1.5e-7);
  const Matrix3d R1 = rotation_matrix(theta + dtheta);
  const Matrix3d R0 = rotation_matrix(theta);
  const Matrix3d expected = rotation_matrix(so3_left_jacobian(theta) * dtheta) * R0;
  EXPECT_LT((R1 - expected).cwiseAbs().maxCoeff(), 1e-13);
}

}  // namespace
}  // namespace si
