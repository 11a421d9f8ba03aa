// The load-controlled driver (analysis/static_run.hpp): natural load stepping of the load
// problem through continuation/, on a spring-net cantilever (tests/model/spring_net_element.hpp).
#include "analysis/static_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../model/spring_net_element.hpp"
#include "../model/test_meshes.hpp"
#include "core/error.hpp"
#include "model/supports.hpp"

namespace si {
namespace {

using testing::SpringNetElement;
using testing::unused_law;

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

StaticResult run(const Cantilever& c, const ShellElement& element, Kinematics kinematics,
                 const Loads& loads, const StaticSettings& s) {
  return run_static(c.mesh, c.dofs, element, unused_law(), kinematics, loads, s);
}

std::vector<double> load_factors(const StaticResult& r) {
  std::vector<double> f;
  for (const StepResult& s : r.steps) f.push_back(s.load_factor);
  return f;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(StaticRun, NominalStepsReachEquilibriumWithBalancedReactions) {
  const Cantilever c;
  const Loads loads = c.tip_load(200.0);
  const StaticResult r = run(c, c.element, Kinematics::kNonlinear, loads, c.settings(2));
  ASSERT_EQ(r.failure, "");
  // The nominal load factors are hit exactly.
  EXPECT_EQ(load_factors(r), (std::vector<double>{0.5, 1.0}));
  for (const StepResult& s : r.steps) {
    EXPECT_LE(s.iterations, 8);
    // The chart Jacobian is unsymmetric (load_problem.hpp).
    EXPECT_EQ(s.linear_solver, LinearSolverKind::kUmfpack);
  }
  // Large deflection: the tip moves up and in (the strip bends, springs keep its length).
  const Vector3d tip = r.steps.back().displacements[0];
  EXPECT_GT(tip.z(), 0.5);
  EXPECT_LT(tip.x(), -0.05);
  // Equilibrium, checked by an independent assembly, and global balance of reactions.
  EXPECT_LT(equilibrium_error(c.mesh, c.dofs, c.element, r.state, fixed_load_vector(c.mesh, loads)),
            1e-10);
  const StepResult& last = r.steps.back();
  EXPECT_NEAR(last.applied_force.z(), 200.0, 1e-12);
  EXPECT_LT((last.reaction_force + last.applied_force).norm(), 1e-10 * 200.0);
  EXPECT_GT(last.energy, 0.0);
  EXPECT_EQ(r.state[c.tip].u, last.displacements[0]);
}

TEST(StaticRun, HalvesATooLargeStepAndKeepsTheConvergedSteps) {
  const Cantilever c;
  StaticSettings s = c.settings(1);
  s.max_iterations = 3;  // too few for the full step (measured: 5), enough for smaller ones
  const StaticResult r = run(c, c.element, Kinematics::kNonlinear, c.tip_load(400.0), s);
  ASSERT_EQ(r.failure, "");
  const std::vector<double> seen = load_factors(r);
  ASSERT_GE(seen.size(), 2u);
  EXPECT_EQ(seen.back(), 1.0);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    // Halved increments: binary fractions of the nominal one, increasing.
    EXPECT_EQ(std::ldexp(seen[i], 5), std::round(std::ldexp(seen[i], 5))) << seen[i];
    if (i > 0) {
      EXPECT_GT(seen[i], seen[i - 1]);
    }
  }
  // Without halving the same step fails and says where and why.
  s.halve_on_failure = false;
  const StaticResult strict = run(c, c.element, Kinematics::kNonlinear, c.tip_load(400.0), s);
  EXPECT_TRUE(strict.steps.empty());
  EXPECT_TRUE(contains(strict.failure, "no convergence beyond load factor 0")) << strict.failure;
  EXPECT_TRUE(contains(strict.failure, "3 iterations")) << strict.failure;
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

TEST(StaticRun, FailedStepReportsLoadFactorAndKeepsConvergedSteps) {
  const Cantilever c;
  const BreakingElement breaking(0.6);
  StaticSettings s = c.settings(4);
  s.max_halvings = 2;
  const StaticResult r = run(c, breaking, Kinematics::kNonlinear, c.tip_load(200.0), s);
  EXPECT_TRUE(contains(r.failure, "residual is not finite")) << r.failure;
  EXPECT_TRUE(contains(r.failure, "last converged load factor")) << r.failure;
  ASSERT_FALSE(r.steps.empty());
  EXPECT_LT(r.steps.back().load_factor, 1.0);
  // `state` is the last converged state.
  EXPECT_EQ(r.state[c.tip].u, r.steps.back().displacements[0]);
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

TEST(StaticRun, ElementErrorsAreRecoverableFailures) {
  const Cantilever c;
  const ThrowingElement throwing;
  StaticSettings s = c.settings(4);
  s.max_halvings = 2;
  const StaticResult r = run(c, throwing, Kinematics::kNonlinear, c.tip_load(200.0), s);
  EXPECT_TRUE(contains(r.failure, "element distorted beyond repair")) << r.failure;
  EXPECT_FALSE(r.steps.empty());
}

TEST(StaticRun, FreeBodyIsReportedAsInsufficientlySupported) {
  const Mesh m = testing::square_plate(3, 3);
  const DofMap dofs = make_dof_map(m, {});
  const SpringNetElement el;
  Loads loads;
  loads.points.push_back({"far_corner", Vector3d(0, 0, 1), false});
  const StaticResult r =
      run_static(m, dofs, el, unused_law(), Kinematics::kNonlinear, loads, StaticSettings{});
  EXPECT_TRUE(r.steps.empty());
  EXPECT_TRUE(contains(r.failure, "load factor 0")) << r.failure;
  EXPECT_TRUE(contains(r.failure, "stiffness matrix is singular")) << r.failure;
  EXPECT_TRUE(
      contains(r.failure, "the model may be insufficiently supported (free rigid-body motion)"))
      << r.failure;
}

TEST(StaticRun, LinearModeFactorsOnceAndScalesWithTheLoad) {
  const Cantilever c;
  const Loads loads = c.tip_load(0.2);
  const StaticResult linear = run(c, c.element, Kinematics::kLinear, loads, c.settings(2));
  ASSERT_EQ(linear.steps.size(), 2u) << linear.failure;
  const StepResult& half = linear.steps[0];
  const StepResult& full = linear.steps[1];
  EXPECT_LT((full.displacements[0] - 2 * half.displacements[0]).norm(),
            1e-12 * full.displacements[0].norm());
  EXPECT_LT((full.reaction_force + full.applied_force).norm(), 1e-10 * 0.2);
  // The tangent predictor of a linear problem is its solution: no Newton iteration.
  EXPECT_EQ(half.iterations + full.iterations, 0);
  EXPECT_EQ(full.linear_solver, LinearSolverKind::kCholmod);
  // A small load: the nonlinear solution agrees to first order (relative difference ~ load).
  const StaticResult nonlinear = run(c, c.element, Kinematics::kNonlinear, loads, c.settings(1));
  ASSERT_EQ(nonlinear.failure, "");
  const Vector3d u_nl = nonlinear.steps.back().displacements[0];
  const Vector3d u_lin = full.displacements[0];
  EXPECT_GT(u_lin.z(), 1e-3);
  EXPECT_LT((u_nl - u_lin).norm(), 2e-2 * u_lin.norm()) << (u_nl - u_lin).norm() / u_lin.norm();
}

// In linear mode a follower pressure is a dead pressure (reference positions).
TEST(StaticRun, LinearModeTreatsFollowerPressureAsDead) {
  const Cantilever c;
  Loads dead, follower;
  dead.pressures.push_back({0.05, false, {}});
  follower.pressures.push_back({0.05, true, {}});
  const StaticResult a = run(c, c.element, Kinematics::kLinear, dead, c.settings(1));
  const StaticResult b = run(c, c.element, Kinematics::kLinear, follower, c.settings(1));
  ASSERT_FALSE(a.steps.empty());
  ASSERT_FALSE(b.steps.empty());
  const Vector3d ua = a.steps.back().displacements[0];
  const Vector3d ub = b.steps.back().displacements[0];
  EXPECT_GT(ua.z(), 1e-4);
  EXPECT_LT((ua - ub).norm(), 1e-12 * ua.norm());
}

// Displacement control: the right edge is pulled up by a prescribed u3; no applied loads, so the
// reactions at the two edges balance each other.
TEST(StaticRun, PrescribedDisplacementScalesWithTheLoadFactor) {
  const Mesh m = testing::square_plate(8, 2, 4.0, 1.0);
  const DofMap dofs =
      make_dof_map(m, {{SupportKind::kClamped, "left", -1, {}}}, {{"right", 2, 1.5}});
  const SpringNetElement el;
  StaticSettings s;
  s.steps = 3;
  s.tolerance = 1e-12;  // the balance of reactions holds to the residual tolerance
  s.record_nodes = {m.node_sets.at("far_corner")[0]};
  const StaticResult r = run_static(m, dofs, el, unused_law(), Kinematics::kNonlinear, Loads{}, s);
  ASSERT_EQ(r.steps.size(), 3u) << r.failure;
  for (const StepResult& step : r.steps) {
    EXPECT_NEAR(step.displacements[0].z(), 1.5 * step.load_factor, 1e-14);
    EXPECT_GT(step.reactions.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_LT(step.reaction_force.norm(), 1e-10 * step.reactions.cwiseAbs().maxCoeff());
  }
}

// A follower pressure: the Jacobian holds its load stiffness (exact: Newton converges in a few
// iterations) and the equilibrium is with the load at the deformed positions.
TEST(StaticRun, FollowerPressureIsInEquilibriumAtTheDeformedPositions) {
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
  const StaticResult r = run_static(m, dofs, el, unused_law(), Kinematics::kNonlinear, loads, s);
  ASSERT_EQ(r.failure, "");
  for (const StepResult& step : r.steps) {
    EXPECT_EQ(step.linear_solver, LinearSolverKind::kUmfpack);
    EXPECT_LE(step.iterations, 6);
  }
  const Eigen::VectorXd f = follower_load_vector(m, loads, r.state);
  EXPECT_LT(equilibrium_error(m, dofs, el, r.state, f), 1e-10);
  // The follower load differs from the dead one at this deflection (it is worth the effort).
  const Eigen::VectorXd f_dead = follower_load_vector(m, loads, reference_state(m));
  EXPECT_GT((f - f_dead).norm(), 1e-3 * f.norm());
  const StepResult& last = r.steps.back();
  EXPECT_LT((last.reaction_force + last.applied_force).norm(), 1e-10 * last.applied_force.norm());
}

// A net with negative spring stiffness has an indefinite K: in linear mode CHOLMOD refuses it
// and the run falls back to UMFPACK.
TEST(StaticRun, LinearModeFallsBackToUmfpackWhenKIsIndefinite) {
  const Cantilever c;
  const SpringNetElement indefinite(-50.0, 500.0, 100.0);
  const StaticResult r = run(c, indefinite, Kinematics::kLinear, c.tip_load(0.01), c.settings(1));
  ASSERT_EQ(r.steps.size(), 1u) << r.failure;
  EXPECT_EQ(r.steps[0].linear_solver, LinearSolverKind::kUmfpack);
  EXPECT_LT((r.steps[0].reaction_force + r.steps[0].applied_force).norm(), 1e-10 * 0.01);
}

// Pseudo-arclength on a load that natural stepping also reaches: the path passes through the
// nominal load factor 1 at the same state (a different method, the same equilibrium).
TEST(StaticRun, PseudoArclengthEndsOnTheLoadFactorOfNaturalStepping) {
  const Cantilever c;
  const Loads loads = c.tip_load(200.0);
  const StaticResult natural = run(c, c.element, Kinematics::kNonlinear, loads, c.settings(4));
  StaticSettings s = c.settings(4);
  s.method = PathMethod::kPseudoArclength;
  s.step = 0.05;
  s.step_max = 0.2;
  s.step_min = 1e-6;
  const StaticResult arclength = run(c, c.element, Kinematics::kNonlinear, loads, s);
  ASSERT_EQ(arclength.failure, "");
  ASSERT_FALSE(arclength.steps.empty());
  EXPECT_EQ(arclength.steps.back().load_factor, 1.0);  // located on load_factor_max
  EXPECT_TRUE(arclength.events.empty());               // no limit point on this path
  const Vector3d a = arclength.steps.back().displacements[0];
  const Vector3d b = natural.steps.back().displacements[0];
  EXPECT_LT((a - b).norm(), 1e-7 * b.norm());
}

TEST(StaticRun, SettingsAreValidated) {
  const Cantilever c;
  const auto make = [&](const StaticSettings& s) {
    run(c, c.element, Kinematics::kNonlinear, Loads{}, s);
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
  s = {};
  s.method = PathMethod::kPseudoArclength;
  s.step = 2 * s.step_max;
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
