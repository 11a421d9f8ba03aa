// The load problem's Jacobian and its chart re-basing (analysis/load_problem.hpp), on a mitc4
// strip rolled by an end moment (the Sze, Liu & Lo 2004 sec. 3.2 set-up) away from equilibrium.
#include "analysis/load_problem.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "model/plate_meshes.hpp"
#include "model/supports.hpp"
#include "shell/shell_element.hpp"
#include "shell/shell_law.hpp"

namespace si {
namespace {

struct RolledStrip {
  Mesh mesh = rectangular_plate_mesh(12.0, 1.0, 8, 1);
  std::unique_ptr<ShellElement> element = make_shell_element(ElementType::kMitc4);
  ShellLaw law = isotropic_shell_law(1.2e6, 0.0, 0.1);
  Loads loads = end_moment();
  LoadProblem problem{mesh,     {{SupportKind::kClamped, "edge_x0", -1, {}}},
                      *element, law,
                      loads,    LoadProblemOptions{}};

  // 2 pi EI / L: a full circle at load factor 1.
  static Loads end_moment() {
    Loads l;
    l.moments.push_back({"edge_x1", Vector3d(0, -2 * M_PI * 100 / 12, 0), false});
    return l;
  }
  // Each node turned about e_y by `turn` times its x / L (the rolled shape's rotations, up to
  // 'turn' at the tip) plus a small out-of-plane part, translations off the circle: far from
  // equilibrium, so that every term of the Jacobian matters.
  cont::Vector point(double turn) const {
    const DofMap& dofs = problem.dofs();
    cont::Vector x = cont::Vector::Zero(problem.size());
    for (int eq = 0; eq < problem.size(); ++eq) {
      const int dof = dofs.free_dofs()[eq];
      const int node = dof / kShellNodeDofs, local = dof % kShellNodeDofs;
      const double s = mesh.nodes[node].x() / 12.0;
      const double rotations[2] = {0.05 * s, -turn * s};  // (a, b) about (V1, V2) = (e_x, e_y)
      x[eq] = local < 3 ? 0.3 * s * (local + 1) : rotations[local - 3];
    }
    return x;
  }
  cont::Vector residual(const cont::Vector& x) {
    cont::Vector F;
    EXPECT_TRUE(problem.residual(x, 1.0, F));
    return F;
  }
  // max_j |J^-1 (J e_j by central differences) - e_j| over the unit vectors e_j: the factored
  // Jacobian against the residual's derivative, column by column.
  double jacobian_error(const cont::Vector& x) {
    const double h = 1e-6;
    double worst = 0;
    EXPECT_TRUE(problem.factorize(x, 1.0));  // the residuals below leave the factors alone
    for (int j = 0; j < problem.size(); ++j) {
      cont::Vector xp = x, xm = x;
      xp[j] += h;
      xm[j] -= h;
      cont::Vector column = (residual(xp) - residual(xm)) / (2 * h);
      EXPECT_TRUE(problem.solve(column));
      column[j] -= 1.0;
      worst = std::max(worst, column.cwiseAbs().maxCoeff());
    }
    return worst;
  }
};

// The chart's drilling term acts on the internal moments only: the end moment's generalised
// forces are constant (loads.hpp). With the residual's moment rows in it (the earlier form), the
// error was drill * M / stiffness, about 5 % here, and Newton stalled on the rolled strip.
TEST(LoadProblem, JacobianMatchesFiniteDifferencesUnderAnEndMoment) {
  RolledStrip strip;
  // Central differences: error ~ h^2 |F'''| and eps |F| / h, both far below 1e-5 of a column.
  EXPECT_LT(strip.jacobian_error(strip.point(1.2)), 1e-5);
}

// A node turned by more than pi/2 is re-based on its frame at x: the states, the residual and
// the point's forces stay; its rotation coordinates become 0; the Jacobian in the new chart is
// exact again; a second adapt() has nothing to do; a point of the old chart is read with the
// old base (point_state_with_base()).
TEST(LoadProblem, AdaptRebasesTurnedNodesAndKeepsTheState) {
  RolledStrip strip;
  LoadProblem& p = strip.problem;
  const cont::Vector before = strip.point(2.6);  // tip at 2.6 rad, nodes beyond x/L = 0.6 > pi/2
  const std::vector<NodeState> old_base = p.chart_base();
  const std::vector<NodeState> states = p.node_states(before);
  const cont::Vector F = strip.residual(before);
  cont::Vector x = before;
  ASSERT_TRUE(p.adapt(x, 1.0));
  EXPECT_EQ(p.rebasings(), 1);
  const std::vector<NodeState> after = p.node_states(x);
  int rebased = 0;
  for (std::size_t n = 0; n < states.size(); ++n) {
    EXPECT_LT((after[n].d - states[n].d).norm(), 1e-14) << "node " << n;
    EXPECT_LT((after[n].v1 - states[n].v1).norm(), 1e-14) << "node " << n;
    EXPECT_EQ(after[n].u, states[n].u) << "node " << n;
    const int eb = p.dofs().equation(DofMap::dof(static_cast<int>(n), 4));
    if (eb < 0) continue;
    const bool turned = std::abs(before[eb]) > M_PI / 2;
    EXPECT_EQ(x[eb] == 0.0, turned) << "node " << n;
    rebased += turned;
  }
  EXPECT_GT(rebased, 0);
  EXPECT_LT((strip.residual(x) - F).cwiseAbs().maxCoeff(), 1e-9 * F.cwiseAbs().maxCoeff());
  EXPECT_LT(strip.jacobian_error(x), 1e-5);
  cont::Vector again = x;
  EXPECT_FALSE(p.adapt(again, 1.0));
  EXPECT_EQ(again, x);

  const LoadPointState now = p.point_state(x, 1.0);
  const LoadPointState old = p.point_state_with_base(old_base, before, 1.0);
  EXPECT_LT((old.internal_force - now.internal_force).cwiseAbs().maxCoeff(),
            1e-9 * now.internal_force.cwiseAbs().maxCoeff());
  EXPECT_NEAR(old.energy, now.energy, 1e-12 * now.energy);
  // ...and the chart is the new one again afterwards.
  EXPECT_LT((strip.residual(x) - F).cwiseAbs().maxCoeff(), 1e-9 * F.cwiseAbs().maxCoeff());
}

// Linear kinematics has a fixed chart: nothing to re-base.
TEST(LoadProblem, LinearKinematicsNeverRebases) {
  RolledStrip strip;
  LoadProblemOptions linear;
  linear.kinematics = Kinematics::kLinear;
  linear.linear_solver = LinearSolverKind::kCholmod;
  LoadProblem p(strip.mesh, {{SupportKind::kClamped, "edge_x0", -1, {}}}, *strip.element, strip.law,
                strip.loads, linear);
  cont::Vector x = strip.point(2.6);
  const cont::Vector before = x;
  EXPECT_FALSE(p.adapt(x, 1.0));
  EXPECT_EQ(x, before);
}

}  // namespace
}  // namespace si
