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

}  // namespace
}  // namespace si
