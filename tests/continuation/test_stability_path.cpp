// Stability along branches of small structural problems with closed-form critical points, and
// branch switching onto a known post-buckled branch (docs/theory/continuation.md, "Stability",
// "Stability events", "Branch switching"). References: the closed forms in
// structural_test_problems.hpp; dense eigen-solves of the same matrices.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Eigenvalues>

#include "../verification_record.hpp"
#include "branch_test_support.hpp"
#include "continuation/branch_switching.hpp"
#include "continuation/natural.hpp"
#include "structural_test_problems.hpp"

namespace si::cont {
namespace {

constexpr double kLocateTol = 1e-6;  // the brief: critical loads to 1e-6 relative

Settings stability_settings(double step_max, double p_max, int modes) {
  Settings s;
  s.step_initial = 0.25 * step_max;
  s.step_max = step_max;
  s.p_min = -1e3;
  s.p_max = p_max;
  s.stability_modes = modes;
  s.detect_bifurcations = true;
  s.event_tolerance = 1e-9;
  return s;
}

double relative(double value, double reference) {
  return std::abs(value / reference - 1.0);
}

// Two limit points P = +-P* (closed form in structural_test_problems.hpp); stability lost at the
// first and regained at the second.
TEST(ContStability, VonMisesTrussLimitLoadsClosedForm) {
  test::VonMisesTruss truss(0.1, 1.0, 1000.0);
  const double p_star = truss.limit_load();
  const Branch branch =
      pseudo_arclength(truss, Vector::Zero(2), 0.0, stability_settings(0.02, 0.5, 2));
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;

  const auto changes = test::events_of(branch, EventType::kStabilityChange);
  ASSERT_EQ(changes.size(), 2u);
  const double expected[] = {p_star, -p_star};
  for (int i = 0; i < 2; ++i) {
    const Event& e = changes[static_cast<std::size_t>(i)];
    EXPECT_TRUE(e.located);
    EXPECT_EQ(e.criticality, Criticality::kLimitPoint);
    EXPECT_EQ(e.negative_before, i == 0 ? 0 : 1);
    EXPECT_EQ(e.negative_after, i == 0 ? 1 : 0);
    EXPECT_LT(relative(e.p, expected[i]), kLocateTol);
    si::test::record_verification("continuation-library",
                                  std::string("von Mises truss: limit load ") +
                                      (i == 0 ? "+P*" : "-P*") + " (stability change)",
                                  expected[i], e.p, kLocateTol,
                                  "closed form P* = 2 EA c*(1/l* - 1/L), l*^3 = b^2 L");
    // The critical mode is the symmetric (vertical) one; at a fold it is the branch's tangent.
    EXPECT_GT(std::abs(e.mode(1)), 1.0 - 1e-6);
    EXPECT_LT(std::abs(e.eigenvalue), 1e-6 * Matrix(truss.tangent(e.x, e.p)).norm());
  }
  EXPECT_NEAR(changes[0].x(1), truss.limit_deflection(), 1e-5);

  // The tangent's limit points agree; the determinant-sign indicator sees no bifurcation.
  const auto folds = test::events_of(branch, EventType::kLimitPoint);
  ASSERT_EQ(folds.size(), 2u);
  for (int i = 0; i < 2; ++i)
    EXPECT_NEAR(folds[static_cast<std::size_t>(i)].p, changes[static_cast<std::size_t>(i)].p,
                1e-9 * p_star);
  EXPECT_TRUE(test::events_of(branch, EventType::kBifurcation).empty());

  // Every point: the count and the lowest eigenvalue against a dense solve of K.
  for (const Point& pt : branch.points) {
    const Vector dense =
        Eigen::SelfAdjointEigenSolver<Matrix>(truss.tangent(pt.x, pt.p), Eigen::EigenvaluesOnly)
            .eigenvalues();
    EXPECT_EQ(pt.negative_eigenvalues, static_cast<int>((dense.array() < 0.0).count()));
    EXPECT_EQ(pt.stable, pt.negative_eigenvalues == 0);
    EXPECT_NEAR(pt.lowest_eigenvalue, dense(0), 1e-10 * dense.cwiseAbs().maxCoeff());
    ASSERT_EQ(pt.eigenvalues.size(), 2);
  }
}

Settings column_settings() {
  Settings s = stability_settings(0.5, 6.0, 1);
  s.step_initial = 0.1;
  return s;
}

// The rigid-bar column: bifurcation at P = k/L on the trivial branch, the tangent restricted to
// the bar's length constraint equal to k/L^2 - P/L at every point.
TEST(ContStability, RigidBarColumnBifurcationOnConstraint) {
  test::RigidBarColumn column(2.0, 0.5);
  const double p_cr = column.critical_load();
  const Branch branch = pseudo_arclength(column, Vector{{0.0, 0.5, 0.0}}, 0.0, column_settings());
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;
  for (const Point& pt : branch.points) {
    EXPECT_NEAR(pt.lowest_eigenvalue, 2.0 / 0.25 - pt.p / 0.5, 1e-10 * 8.0) << "P = " << pt.p;
    EXPECT_EQ(pt.negative_eigenvalues, pt.p > p_cr ? 1 : 0);
  }
  const auto changes = test::events_of(branch, EventType::kStabilityChange);
  ASSERT_EQ(changes.size(), 1u);
  const Event& e = changes[0];
  EXPECT_EQ(e.criticality, Criticality::kBifurcation);
  EXPECT_LT(relative(e.p, p_cr), kLocateTol);
  si::test::record_verification("continuation-library",
                                "rigid-bar column: bifurcation load (stability change)", p_cr, e.p,
                                kLocateTol, "closed form P_cr = k/L");
  EXPECT_GT(std::abs(e.mode(0)), 1.0 - 1e-12);  // sway: along u, tangent to the constraint
  // The determinant-sign indicator (sign det J * sign dp/ds) flips at the same point.
  const auto bifurcations = test::events_of(branch, EventType::kBifurcation);
  ASSERT_EQ(bifurcations.size(), 1u);
  EXPECT_NEAR(bifurcations[0].p, e.p, 1e-8 * p_cr);
  EXPECT_TRUE(test::events_of(branch, EventType::kLimitPoint).empty());
}

// Both halves of the post-buckled branch: every point satisfies P L sin(theta) = k theta, keeps
// the bar's length, is stable, and carries its branch id.
TEST(ContStability, RigidBarColumnBranchSwitchingLandsOnPostBuckledBranch) {
  const double k = 2.0;
  const double L = 0.5;
  test::RigidBarColumn column(k, L);
  const Settings settings = column_settings();
  const Branch fundamental = pseudo_arclength(column, Vector{{0.0, L, 0.0}}, 0.0, settings);
  const auto changes = test::events_of(fundamental, EventType::kStabilityChange);
  ASSERT_EQ(changes.size(), 1u);
  double worst = 0.0;
  std::vector<double> sides;
  for (int direction : {1, -1}) {
    BranchSwitch options;
    options.direction = direction;
    options.branch_id = direction > 0 ? 1 : 2;
    const Branch post = switch_branch(column, changes[0], settings, options);
    ASSERT_EQ(post.status, Status::kReachedBound) << post.reason;
    ASSERT_GT(post.points.size(), 5u);
    const double side = test::RigidBarColumn::angle(post.points.front().x) > 0.0 ? 1.0 : -1.0;
    for (const Point& pt : post.points) {
      const double theta = test::RigidBarColumn::angle(pt.x);
      EXPECT_EQ(pt.branch_id, options.branch_id);
      EXPECT_GT(side * theta, 0.0);  // never back on the trivial branch or the other half
      const double closed_form = k * theta / (L * std::sin(theta));
      worst = std::max(worst, relative(pt.p, closed_form));
      EXPECT_LT(relative(pt.p, closed_form), 1e-9) << "theta = " << theta;
      EXPECT_NEAR(pt.x.head(2).norm(), L, 1e-10);
      EXPECT_TRUE(pt.stable) << "theta = " << theta;
      EXPECT_GE(pt.p, column.critical_load() * (1.0 - 1e-12));
    }
    EXPECT_NEAR(post.points.back().p, 6.0, 1e-12);
    sides.push_back(side);
  }
  EXPECT_EQ(sides[0], -sides[1]);  // the two directions give the two mirror halves
  si::test::record_verification_absolute(
      "continuation-library",
      "rigid-bar column: post-buckled points vs P = k theta/(L sin theta), max relative error", 0.0,
      worst, 1e-9, "closed form");
}

// The discrete beam on an elastic foundation: the first three stability changes are the discrete
// buckling loads P_3 < P_4 < P_2 (c = 80 pi^4 makes m = 3 critical), each a bifurcation whose mode
// is the discrete sine with that wave number; against a dense generalized eigen-solve of the same
// matrices, and within the O(h^2) discretisation error of the continuum loads.
TEST(ContStability, BeamOnFoundationBucklingLoadsAndModes) {
  const double pi = std::acos(-1.0);
  const int intervals = 40;
  test::BeamOnFoundation beam(intervals, 1.0, 1.0, 80.0 * std::pow(pi, 4));
  Settings s = stability_settings(20.0, 250.0, 3);
  const Branch branch = pseudo_arclength(beam, Vector::Zero(beam.size()), 0.0, s);
  ASSERT_EQ(branch.status, Status::kReachedBound) << branch.reason;

  const Matrix K = beam.stiffness().block(1, 1, intervals - 1, intervals - 1);
  const Matrix G = beam.geometric().block(1, 1, intervals - 1, intervals - 1);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> dense(K, G);

  const auto changes = test::events_of(branch, EventType::kStabilityChange);
  ASSERT_EQ(changes.size(), 3u);
  const int wave[] = {3, 4, 2};
  for (int i = 0; i < 3; ++i) {
    const Event& e = changes[static_cast<std::size_t>(i)];
    const int m = wave[i];
    EXPECT_EQ(e.criticality, Criticality::kBifurcation);
    EXPECT_EQ(e.negative_before, i);
    EXPECT_EQ(e.negative_after, i + 1);
    EXPECT_LT(relative(e.p, beam.discrete_load(m)), kLocateTol) << "m = " << m;
    EXPECT_LT(relative(e.p, dense.eigenvalues()(i)), kLocateTol) << "m = " << m;
    const double discretisation = relative(beam.discrete_load(m), beam.continuum_load(m));
    EXPECT_LT(relative(e.p, beam.continuum_load(m)), 1.01 * discretisation + kLocateTol);
    EXPECT_LT(discretisation, 2e-2);
    si::test::record_verification(
        "continuation-library",
        "beam on foundation N = 40: buckling load m = " + std::to_string(m) + " (discrete)",
        beam.discrete_load(m), e.p, kLocateTol, "closed form of the discrete problem");
    // The mode: the discrete sine sin(m pi i/N), also the dense eigenvector.
    Vector sine(intervals + 1);
    for (int j = 0; j <= intervals; ++j) sine(j) = std::sin(m * pi * j / intervals);
    const Vector w = e.mode.head(intervals + 1);
    EXPECT_GT(std::abs(w.dot(sine)) / (w.norm() * sine.norm()), 1.0 - 1e-10) << "m = " << m;
    int sign_changes = 0;
    for (int j = 2; j < intervals; ++j) sign_changes += (w(j) > 0.0) != (w(j - 1) > 0.0);
    EXPECT_EQ(sign_changes, m - 1);
    const Vector v = dense.eigenvectors().col(i);
    EXPECT_GT(std::abs(w.segment(1, intervals - 1).dot(v)) /
                  (w.segment(1, intervals - 1).norm() * v.norm()),
              1.0 - 1e-10);
  }
  // Determinant-sign indicator: the same three bifurcations.
  const auto bifurcations = test::events_of(branch, EventType::kBifurcation);
  ASSERT_EQ(bifurcations.size(), 3u);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(bifurcations[static_cast<std::size_t>(i)].p, changes[static_cast<std::size_t>(i)].p,
                1e-8 * changes[0].p);
}

TEST(ContStability, OffByDefaultNothingComputed) {
  test::RigidBarColumn column(2.0, 0.5);
  Settings s = column_settings();
  s.stability_modes = 0;
  const Branch branch = pseudo_arclength(column, Vector{{0.0, 0.5, 0.0}}, 0.0, s);
  ASSERT_EQ(branch.status, Status::kReachedBound);
  EXPECT_EQ(column.stability_calls(), 0);
  EXPECT_TRUE(test::events_of(branch, EventType::kStabilityChange).empty());
  for (const Point& pt : branch.points) {
    EXPECT_EQ(pt.negative_eigenvalues, -1);
    EXPECT_EQ(pt.eigenvalues.size(), 0);
    EXPECT_TRUE(std::isnan(pt.lowest_eigenvalue));
  }
}

TEST(ContStability, ProblemWithoutStabilityRefused) {
  test::CircleProblem circle;
  Settings s;
  s.stability_modes = 2;
  try {
    pseudo_arclength(circle, Vector::Constant(1, 1.0), 0.0, s);
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "continuation.stability_modes = 2 but the problem does not provide stability()");
  }
}

TEST(ContStability, SwitchBranchRefusesOtherEvents) {
  test::VonMisesTruss truss(0.1, 1.0, 1000.0);
  const Branch branch =
      pseudo_arclength(truss, Vector::Zero(2), 0.0, stability_settings(0.02, 0.5, 1));
  const auto changes = test::events_of(branch, EventType::kStabilityChange);
  ASSERT_FALSE(changes.empty());
  EXPECT_THROW(switch_branch(truss, changes[0], stability_settings(0.02, 0.5, 1)),
               std::invalid_argument);  // a limit point, not a bifurcation
}

// The stability fields survive a checkpoint bit for bit, and a branch switched from the loaded
// event is the one switched from the original.
TEST(ContStability, CheckpointKeepsStabilityAndSwitchingData) {
  test::RigidBarColumn column(2.0, 0.5);
  Settings s = column_settings();
  s.checkpoint_path = ::testing::TempDir() + "stability_checkpoint.json";
  s.checkpoint_writer = test::plain_file_writer();
  s.checkpoint_interval = 1;
  const Branch branch = pseudo_arclength(column, Vector{{0.0, 0.5, 0.0}}, 0.0, s);
  const Checkpoint loaded = load_checkpoint(s.checkpoint_path);
  std::remove(s.checkpoint_path.c_str());
  ASSERT_EQ(loaded.branch.points.size(), branch.points.size());
  for (std::size_t i = 0; i < branch.points.size(); ++i) {
    const Point& a = branch.points[i];
    const Point& b = loaded.branch.points[i];
    EXPECT_EQ(a.negative_eigenvalues, b.negative_eigenvalues);
    EXPECT_EQ(a.stable, b.stable);
    EXPECT_EQ(a.lowest_eigenvalue, b.lowest_eigenvalue);
    EXPECT_EQ(a.eigenvalues, b.eigenvalues);
  }
  const Event original = test::events_of(branch, EventType::kStabilityChange).at(0);
  const Event read = test::events_of(loaded.branch, EventType::kStabilityChange).at(0);
  EXPECT_EQ(read.criticality, original.criticality);
  EXPECT_EQ(read.eigenvalue, original.eigenvalue);
  EXPECT_EQ(read.mode, original.mode);
  EXPECT_EQ(read.tangent_x, original.tangent_x);
  s.checkpoint_path.clear();
  s.checkpoint_interval = 0;
  const Branch a = switch_branch(column, original, s);
  const Branch b = switch_branch(column, read, s);
  ASSERT_EQ(a.points.size(), b.points.size());
  EXPECT_EQ(a.points.back().x, b.points.back().x);
}

// A run stopped before the bifurcation and resumed from its checkpoint repeats the uninterrupted
// one, stability and events included.
TEST(ContStability, ResumedRunRepeatsTheUninterruptedOne) {
  const Vector x0{{0.0, 0.5, 0.0}};
  Settings s = column_settings();
  test::RigidBarColumn column(2.0, 0.5);
  const Branch full = pseudo_arclength(column, x0, 0.0, s);
  s.checkpoint_path = ::testing::TempDir() + "stability_resume.json";
  s.checkpoint_writer = test::plain_file_writer();
  s.checkpoint_interval = 3;
  int calls = 0;
  const Branch cut = pseudo_arclength(
      column, x0, 0.0, s, [&calls](const Point&, const Branch&) { return ++calls < 8; });
  ASSERT_EQ(cut.status, Status::kStoppedByCallback);
  ASSERT_TRUE(test::events_of(cut, EventType::kStabilityChange).empty());
  const Checkpoint checkpoint = load_checkpoint(s.checkpoint_path);
  std::remove(s.checkpoint_path.c_str());
  s.checkpoint_path.clear();
  s.checkpoint_interval = 0;
  const Branch resumed = pseudo_arclength(column, checkpoint, s);
  ASSERT_EQ(resumed.points.size(), full.points.size());
  for (std::size_t i = 0; i < full.points.size(); ++i) {
    EXPECT_EQ(resumed.points[i].p, full.points[i].p);
    EXPECT_EQ(resumed.points[i].negative_eigenvalues, full.points[i].negative_eigenvalues);
    EXPECT_EQ(resumed.points[i].eigenvalues, full.points[i].eigenvalues);
  }
  const auto a = test::events_of(full, EventType::kStabilityChange);
  const auto b = test::events_of(resumed, EventType::kStabilityChange);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(a[0].p, b[0].p);
  EXPECT_EQ(a[0].mode, b[0].mode);
}

}  // namespace
}  // namespace si::cont
