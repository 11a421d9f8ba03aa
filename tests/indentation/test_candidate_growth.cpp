// Issue 4 item 2: the candidate set grows when contact spreads to its edge. A run that starts
// with a deliberately small set (nodes within 0.05 mm of travel) must end with a larger one and
// the same path as a run whose set holds every node the indenter can reach from the start.
#include <gtest/gtest.h>

#include <cmath>

#include "continuation/natural.hpp"
#include "indentation_test_support.hpp"

namespace si {
namespace {

cont::Branch natural_path(IndentationProblem& p) {
  cont::Settings s;
  s.method = cont::Method::kNatural;
  s.parameter_values = {0.25, 0.5, 0.75, 1.0, 1.25, 1.5};
  s.step_initial = 0.25;
  s.step_max = 0.25;
  s.step_min = 1e-4;
  s.newton = testing::tight_kinsol_settings(p);
  s.newton.relative_tolerance = 1e-10;
  return cont::natural(p, p.initial_point(), 0.0, s);
}

// Points before a growth are shorter: the new candidates were appended with lambda = 0.
double force_at(IndentationProblem& p, const cont::Point& pt) {
  cont::Vector z = cont::Vector::Zero(p.size());
  z.head(pt.x.size()) = pt.x;
  return p.evaluate(z, pt.p).force;
}

TEST(CandidateGrowth, SmallInitialSetGrowsAndGivesTheSamePath) {
  IndentationOptions small;
  small.candidate_depth = 0.05;
  testing::IndentationFixture a(testing::coarse_cap_case("nonlinear", "[0/0]2S", "quarter"), small);
  const std::size_t initial = a.problem->candidates().size();
  const cont::Branch ba = natural_path(*a.problem);
  ASSERT_EQ(ba.status, cont::Status::kCompleted) << ba.reason;
  EXPECT_GT(a.problem->candidates().size(), initial);

  testing::IndentationFixture b(testing::coarse_cap_case("nonlinear", "[0/0]2S", "quarter"));
  const cont::Branch bb = natural_path(*b.problem);
  ASSERT_EQ(bb.status, cont::Status::kCompleted) << bb.reason;
  // Compare at the requested depths (the two runs may take different substeps).
  const auto at = [](const cont::Branch& branch, double depth) -> const cont::Point& {
    for (const cont::Point& pt : branch.points)
      if (std::abs(pt.p - depth) < 1e-12) return pt;
    ADD_FAILURE() << "no point at depth " << depth;
    return branch.points.back();
  };
  for (double depth : {0.25, 0.5, 0.75, 1.0, 1.25, 1.5}) {
    const double fa = force_at(*a.problem, at(ba, depth));
    const double fb = force_at(*b.problem, at(bb, depth));
    EXPECT_NEAR(fa, fb, 1e-7 * (1 + fb)) << "depth " << depth;
  }
  EXPECT_EQ(ba.points.back().x.size(), a.problem->size());
  EXPECT_GT(a.problem->evaluate(ba.points.back().x, ba.points.back().p).contact_nodes, 1);
}

// Each growth takes a margin of a few node spacings around the nodes that came within reach, so
// that the set grows in few events (each re-lays the Jacobian's pattern): on 24 steps of
// 0.0625 mm from a set that starts with the nodes within 0.05 mm of travel.
TEST(CandidateGrowth, GrowsInFewEvents) {
  IndentationOptions small;
  small.candidate_depth = 0.05;
  testing::IndentationFixture a(testing::coarse_cap_case("nonlinear", "[0/0]2S", "quarter"), small);
  cont::Settings s;
  s.method = cont::Method::kNatural;
  for (int k = 1; k <= 24; ++k) s.parameter_values.push_back(0.0625 * k);
  s.step_initial = s.step_max = 0.0625;
  s.step_min = 1e-4;
  s.newton = testing::tight_kinsol_settings(*a.problem);
  const cont::Branch b = cont::natural(*a.problem, a.problem->initial_point(), 0.0, s);
  ASSERT_EQ(b.status, cont::Status::kCompleted) << b.reason;
  int growths = 0;
  for (std::size_t k = 1; k < b.points.size(); ++k)
    growths += b.points[k].x.size() != b.points[k - 1].x.size();
  // Without the margin: 3 growths (measured).
  EXPECT_EQ(growths, 1);
}

}  // namespace
}  // namespace si
