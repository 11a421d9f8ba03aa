#include "analysis/static_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "../model/spring_net_element.hpp"
#include "../model/test_meshes.hpp"
#include "core/error.hpp"
#include "model/supports.hpp"

namespace si {
namespace {

using testing::SpringNetElement;
using testing::unused_law;

// Relative residuals below this are roundoff (measured floor 3e-14..1.4e-13): no rate there.
constexpr double kRoundoff = 1e-12;

std::string history(const StepResult& r) {
  std::ostringstream os;
  os << "residuals:";
  for (double x : r.residual_history) os << ' ' << x;
  return os.str();
}

// A cantilever strip clamped on the left, transverse load on the right edge: large rotations of
// the spring net at full load.
struct Cantilever {
  Mesh mesh = testing::square_plate(8, 2, 4.0, 1.0);
  DofMap dofs = make_dof_map(mesh, {{SupportKind::kClamped, "left", -1, {}}});
  SpringNetElement element;
  int tip = mesh.node_sets.at("far_corner")[0];

  Loads tip_load(double total) const {
    Loads l;
    l.points.push_back({"right", Vector3d(0, 0, total), false});
    return l;
  }
  StaticSettings settings(int steps) const {
    StaticSettings s;
    s.steps = steps;
    s.tolerance = 1e-10;
    s.record_nodes = {tip};
    return s;
  }
};

// Relative free-dof residual of an independent assembly at `state`.
double equilibrium_error(const Mesh& m, const DofMap& dofs, const ShellElement& el,
                         const std::vector<NodeState>& state, const Eigen::VectorXd& f_ext) {
  const Assembler assembler(m, dofs, el, unused_law(), Kinematics::kNonlinear);
  Assembly a = assembler.make_assembly();
  assembler.assemble(state, {true, false}, a);
  return dofs.restrict_to_free(a.internal_force - f_ext).norm() / f_ext.norm();
}

TEST(StaticSolver, NewtonConvergesQuadraticallyToEquilibrium) {
  const Cantilever c;
  const Loads loads = c.tip_load(200.0);
  StaticSolver solver(c.mesh, c.dofs, c.element, unused_law(), Kinematics::kNonlinear, loads,
                      c.settings(2));
  std::vector<NodeState> state = reference_state(c.mesh);
  const auto& steps = solver.solve(state);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_DOUBLE_EQ(steps[0].load_factor, 0.5);
  EXPECT_DOUBLE_EQ(steps[1].load_factor, 1.0);
  for (const StepResult& s : steps) {
    const std::string h = history(s);
    // Quadratic: once the residual is small, r_{k+1} <= C r_k^2 with C = 10. Measured (step 1):
    // 1, 0.334, 9.7e-4, 2.4e-8, 3.1e-14, i.e. r_{k+1} / r_k^2 = 0.025 then roundoff.
    bool checked = false;
    for (std::size_t k = 0; k + 1 < s.residual_history.size(); ++k) {
      const double r = s.residual_history[k], next = s.residual_history[k + 1];
      if (r < 1e-2 && next > kRoundoff) {
        EXPECT_LT(next, 10.0 * r * r) << "residuals:" << h;
        checked = true;
      }
    }
    EXPECT_TRUE(checked) << "no asymptotic iterations to check, residuals:" << h;
    EXPECT_LE(s.iterations, 8) << h;
    EXPECT_EQ(s.linear_solver, LinearSolverKind::kCholmod);
  }
  // Large deflection: the tip moves up and in (the strip bends, springs keep its length).
  const Vector3d tip = steps.back().displacements[0];
  EXPECT_GT(tip.z(), 0.5);
  EXPECT_LT(tip.x(), -0.05);
  // Equilibrium, checked by an independent assembly, and global balance of reactions.
  EXPECT_LT(equilibrium_error(c.mesh, c.dofs, c.element, state, fixed_load_vector(c.mesh, loads)),
            1e-10);
  const StepResult& last = steps.back();
  EXPECT_NEAR(last.applied_force.z(), 200.0, 1e-12);
  EXPECT_LT((last.reaction_force + last.applied_force).norm(), 1e-10 * 200.0);
  EXPECT_GT(last.energy, 0.0);
}

TEST(StaticSolver, HalvesATooLargeStepAndKeepsTheConvergedSteps) {
  const Cantilever c;
  StaticSettings s = c.settings(1);
  s.max_iterations = 4;  // the full step needs 5 (measured), half steps need 4
  StaticSolver solver(c.mesh, c.dofs, c.element, unused_law(), Kinematics::kNonlinear,
                      c.tip_load(400.0), s);
  std::vector<NodeState> state = reference_state(c.mesh);
  std::vector<double> seen;
  solver.solve(state, [&](const StepResult& r, const std::vector<NodeState>&) {
    seen.push_back(r.load_factor);
    return true;
  });
  // Halved to 0.5; back to the full increment, which fails again from 0.5; then 0.75 and 1.
  EXPECT_EQ(seen, (std::vector<double>{0.5, 0.75, 1.0}));
  EXPECT_EQ(solver.steps().size(), seen.size());
  // Without halving the same step fails and says where and why.
  s.halve_on_failure = false;
  StaticSolver strict(c.mesh, c.dofs, c.element, unused_law(), Kinematics::kNonlinear,
                      c.tip_load(400.0), s);
  std::vector<NodeState> state2 = reference_state(c.mesh);
  try {
    strict.solve(state2);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
    EXPECT_NE(std::string(e.what()).find("static step to load factor 1 failed: no convergence in "
                                         "4 Newton iterations"),
              std::string::npos)
        << e.what();
  }
}

// An element that breaks (non-finite response) once any node moves more than `limit`: steps
// below the limit converge, the step across it fails however much it is halved.
class BreakingElement : public SpringNetElement {
 public:
  explicit BreakingElement(double limit) : limit_(limit) {}
  void compute(const ElementGeometry& geo, const std::array<NodeState, 4>& nodes,
               const ShellLaw& law, Kinematics kin, const ElementRequest& req,
               ElementResponse& out) const override {
    SpringNetElement::compute(geo, nodes, law, kin, req, out);
    for (const NodeState& n : nodes)
      if (n.u.norm() > limit_) out.force[0] = std::nan("");
  }

 private:
  double limit_;
};

TEST(StaticSolver, FailedStepReportsLoadFactorAndKeepsConvergedSteps) {
  const Cantilever c;
  const BreakingElement breaking(0.6);
  StaticSettings s = c.settings(4);
  s.max_halvings = 2;
  StaticSolver solver(c.mesh, c.dofs, breaking, unused_law(), Kinematics::kNonlinear,
                      c.tip_load(200.0), s);
  std::vector<NodeState> state = reference_state(c.mesh);
  try {
    solver.solve(state);
    FAIL() << "the breaking element did not break";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
    EXPECT_NE(std::string(e.what()).find("residual is not finite after 2 step halvings"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("last converged load factor"), std::string::npos);
  }
  ASSERT_FALSE(solver.steps().empty());
  EXPECT_LT(solver.steps().back().load_factor, 1.0);
  // `state` is the last converged state.
  EXPECT_EQ(state[c.tip].u, solver.steps().back().displacements[0]);
}

// Same with an element that throws a numerical error (e.g. an inverted element) past the limit:
// a recoverable failure, halved like a divergence, and reported with the element's reason.
class ThrowingElement : public SpringNetElement {
 public:
  void compute(const ElementGeometry& geo, const std::array<NodeState, 4>& nodes,
               const ShellLaw& law, Kinematics kin, const ElementRequest& req,
               ElementResponse& out) const override {
    for (const NodeState& n : nodes)
      if (n.u.norm() > 0.6) throw_numerical("element distorted beyond repair");
    SpringNetElement::compute(geo, nodes, law, kin, req, out);
  }
};

TEST(StaticSolver, ElementErrorsAreRecoverableFailures) {
  const Cantilever c;
  const ThrowingElement throwing;
  StaticSettings s = c.settings(4);
  s.max_halvings = 2;
  StaticSolver solver(c.mesh, c.dofs, throwing, unused_law(), Kinematics::kNonlinear,
                      c.tip_load(200.0), s);
  std::vector<NodeState> state = reference_state(c.mesh);
  try {
    solver.solve(state);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
    EXPECT_NE(std::string(e.what()).find("element distorted beyond repair after 2 step halvings"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(solver.steps().empty());
}

TEST(StaticSolver, FreeBodyIsReportedAsInsufficientlySupported) {
  const Mesh m = testing::square_plate(3, 3);
  const DofMap dofs = make_dof_map(m, {});
  const SpringNetElement el;
  Loads loads;
  loads.points.push_back({"far_corner", Vector3d(0, 0, 1), false});
  StaticSolver solver(m, dofs, el, unused_law(), Kinematics::kNonlinear, loads, StaticSettings{});
  std::vector<NodeState> state = reference_state(m);
  try {
    solver.solve(state);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kNumerical);
    const std::string what = e.what();
    EXPECT_NE(what.find("load factor 0.1"), std::string::npos) << what;
    EXPECT_NE(what.find("stiffness matrix is singular"), std::string::npos) << what;
    EXPECT_NE(what.find("the model may be insufficiently supported (free rigid-body motion)"),
              std::string::npos)
        << what;
  }
}

TEST(StaticSolver, LinearModeSolvesOnceAndScalesWithTheLoad) {
  const Cantilever c;
  const Loads loads = c.tip_load(0.2);
  StaticSolver linear(c.mesh, c.dofs, c.element, unused_law(), Kinematics::kLinear, loads,
                      c.settings(2));
  std::vector<NodeState> state = reference_state(c.mesh);
  const auto& steps = linear.solve(state);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_LT((steps[1].displacements[0] - 2 * steps[0].displacements[0]).norm(),
            1e-12 * steps[1].displacements[0].norm());
  EXPECT_LT((steps[1].reaction_force + steps[1].applied_force).norm(), 1e-10 * 0.2);
  // A small load: the nonlinear solution agrees to first order (relative difference ~ load).
  StaticSolver nonlinear(c.mesh, c.dofs, c.element, unused_law(), Kinematics::kNonlinear, loads,
                         c.settings(1));
  std::vector<NodeState> state_nl = reference_state(c.mesh);
  const Vector3d u_nl = nonlinear.solve(state_nl).back().displacements[0];
  const Vector3d u_lin = steps[1].displacements[0];
  EXPECT_GT(u_lin.z(), 1e-3);
  EXPECT_LT((u_nl - u_lin).norm(), 2e-2 * u_lin.norm()) << (u_nl - u_lin).norm() / u_lin.norm();
}

// In linear mode a follower pressure is a dead pressure (reference positions).
TEST(StaticSolver, LinearModeTreatsFollowerPressureAsDead) {
  const Cantilever c;
  Loads dead, follower;
  dead.pressures.push_back({0.05, false, {}});
  follower.pressures.push_back({0.05, true, {}});
  std::vector<NodeState> s1 = reference_state(c.mesh), s2 = s1;
  StaticSolver a(c.mesh, c.dofs, c.element, unused_law(), Kinematics::kLinear, dead, c.settings(1));
  StaticSolver b(c.mesh, c.dofs, c.element, unused_law(), Kinematics::kLinear, follower,
                 c.settings(1));
  const Vector3d ua = a.solve(s1).back().displacements[0];
  const Vector3d ub = b.solve(s2).back().displacements[0];
  EXPECT_GT(ua.z(), 1e-4);
  EXPECT_LT((ua - ub).norm(), 1e-12 * ua.norm());
}

// Displacement control: the right edge is pulled up by a prescribed u3; no applied loads, so the
// reactions at the two edges balance each other.
TEST(StaticSolver, PrescribedDisplacementScalesWithTheLoadFactor) {
  const Mesh m = testing::square_plate(8, 2, 4.0, 1.0);
  const DofMap dofs =
      make_dof_map(m, {{SupportKind::kClamped, "left", -1, {}}}, {{"right", 2, 1.5}});
  const SpringNetElement el;
  StaticSettings s;
  s.steps = 3;
  s.tolerance = 1e-12;  // the balance of reactions holds to the residual tolerance
  s.record_nodes = {m.node_sets.at("far_corner")[0]};
  StaticSolver solver(m, dofs, el, unused_law(), Kinematics::kNonlinear, Loads{}, s);
  std::vector<NodeState> state = reference_state(m);
  const auto& steps = solver.solve(state);
  ASSERT_EQ(steps.size(), 3u);
  for (const StepResult& r : steps) {
    EXPECT_NEAR(r.displacements[0].z(), 1.5 * r.load_factor, 1e-14);
    EXPECT_GT(r.reaction_force.norm() + std::abs(r.reactions.maxCoeff()), 0.0);
    EXPECT_LT(r.reaction_force.norm(), 1e-10 * r.reactions.cwiseAbs().maxCoeff());
  }
}

TEST(StaticSolver, FollowerPressureUsesUmfpackAndConvergesQuadratically) {
  const Mesh m = testing::square_plate(6, 6, 2.0, 2.0);
  const DofMap dofs = make_dof_map(m, {{SupportKind::kHinged, "left", -1, {}},
                                       {SupportKind::kHinged, "right", -1, {}},
                                       {SupportKind::kHinged, "bottom", -1, {}},
                                       {SupportKind::kHinged, "top", -1, {}}});
  const SpringNetElement el;
  Loads loads;
  loads.pressures.push_back({30.0, true, {}});
  StaticSettings s;
  s.steps = 2;
  s.tolerance = 1e-10;
  StaticSolver solver(m, dofs, el, unused_law(), Kinematics::kNonlinear, loads, s);
  std::vector<NodeState> state = reference_state(m);
  const auto& steps = solver.solve(state);
  for (const StepResult& r : steps) {
    EXPECT_EQ(r.linear_solver, LinearSolverKind::kUmfpack);
    const std::string h = history(r);
    for (std::size_t k = 0; k + 1 < r.residual_history.size(); ++k) {
      const double x = r.residual_history[k], next = r.residual_history[k + 1];
      if (x >= 1e-2 || next <= kRoundoff) continue;
      EXPECT_LT(next, 10.0 * x * x) << h;
    }
  }
  // Equilibrium with the follower load at the final (deformed) positions.
  const Eigen::VectorXd f = follower_load_vector(m, loads, state);
  EXPECT_LT(equilibrium_error(m, dofs, el, state, f), 1e-10);
  // The follower load differs from the dead one at this deflection (it is worth the effort).
  const Eigen::VectorXd f_dead = follower_load_vector(m, loads, reference_state(m));
  EXPECT_GT((f - f_dead).norm(), 1e-3 * f.norm());
  EXPECT_LT((steps.back().reaction_force + steps.back().applied_force).norm(),
            1e-10 * steps.back().applied_force.norm());
}

// A net with negative spring stiffness has an indefinite tangent: CHOLMOD refuses it and the
// solver falls back to UMFPACK.
TEST(StaticSolver, FallsBackToUmfpackWhenTheTangentIsIndefinite) {
  const Cantilever c;
  const SpringNetElement indefinite(-50.0, 500.0, 100.0);
  StaticSolver solver(c.mesh, c.dofs, indefinite, unused_law(), Kinematics::kNonlinear,
                      c.tip_load(0.01), c.settings(1));
  std::vector<NodeState> state = reference_state(c.mesh);
  const auto& steps = solver.solve(state);
  ASSERT_EQ(steps.size(), 1u);
  EXPECT_EQ(steps[0].linear_solver, LinearSolverKind::kUmfpack);
  EXPECT_LT(equilibrium_error(c.mesh, c.dofs, indefinite, state,
                              fixed_load_vector(c.mesh, c.tip_load(0.01))),
            1e-10);
}

TEST(StaticSolver, SettingsAreValidatedAtConstruction) {
  const Cantilever c;
  const auto make = [&](StaticSettings s) {
    StaticSolver solver(c.mesh, c.dofs, c.element, unused_law(), Kinematics::kNonlinear, Loads{},
                        s);
  };
  StaticSettings s;
  s.steps = 0;
  EXPECT_THROW(make(s), Error);
  s = {};
  s.tolerance = 0;
  EXPECT_THROW(make(s), Error);
  s = {};
  s.max_iterations = 0;
  EXPECT_THROW(make(s), Error);
  s = {};
  s.linear_solver = LinearSolverKind::kKlu;  // a general LU, not one of the static run's
  EXPECT_THROW(make(s), Error);
  s = {};
  s.record_nodes = {1000};
  EXPECT_THROW(make(s), Error);
  try {
    s = {};
    s.max_halvings = -1;
    make(s);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().key, "static.max_halvings");
  }
}

}  // namespace
}  // namespace si
