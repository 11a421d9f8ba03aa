// Issue 5: a killed run resumed from its checkpoint reproduces the uninterrupted run's path to
// 1e-10, for both continuation methods.
#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "../indentation/indentation_test_support.hpp"
#include "analysis/indentation_run.hpp"

namespace si {
namespace {

CaseFile resume_case(PathMethod method, LocalContactModel local) {
  CaseFile c = testing::coarse_cap_path_case("[0/0]2S", method, 1.0, 0.1, 0.15);
  c.contact.local = local;
  return c;
}

struct Killed : std::runtime_error {
  Killed() : std::runtime_error("killed") {}
};

void expect_resume_reproduces(PathMethod method, const std::string& name,
                              LocalContactModel local = LocalContactModel::kNone) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  PathControl control;
  control.checkpoint = (dir / "checkpoint.json").string();
  control.checkpoint_interval = 3;

  IndentationSetup whole(resume_case(method, local), 1);
  const PathResult a = run_indentation_path(whole);
  ASSERT_TRUE(a.completed) << a.reason;
  ASSERT_GT(a.points.size(), 7u);

  {  // killed after 5 points: the last checkpoint is the one of point 3
    IndentationSetup first(resume_case(method, local), 1);
    int seen = 0;
    const auto kill_after_five = [&](const PathPoint&, const cont::Vector&) {
      if (++seen == 5) throw Killed();
      return true;
    };
    EXPECT_THROW(run_indentation_path(first, kill_after_five, control), Killed);
  }
  IndentationSetup second(resume_case(method, local), 1);
  control.resume = true;
  std::size_t computed = 0;  // points computed after the resume (the others come from disk)
  const auto count = [&](const PathPoint&, const cont::Vector&) { return ++computed > 0; };
  const PathResult b = run_indentation_path(second, count, control);
  ASSERT_TRUE(b.completed) << b.reason;
  EXPECT_LE(computed, a.points.size() - 3);  // it did start from the checkpoint
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const IndentationState& x = a.points[i].state;
    const IndentationState& y = b.points[i].state;
    EXPECT_NEAR(x.depth, y.depth, 1e-10 * (1 + x.depth)) << i;
    EXPECT_NEAR(x.force, y.force, 1e-10 * (1 + x.force)) << i;
    EXPECT_NEAR(x.energy, y.energy, 1e-10 * (1 + x.energy)) << i;
    EXPECT_NEAR(a.points[i].work, b.points[i].work, 1e-10 * (1 + a.points[i].work)) << i;
    EXPECT_NEAR(x.local_indentation, y.local_indentation, 1e-10) << i;
  }
}

TEST(IndentationResume, PseudoArclengthResumedRunReproducesThePath) {
  expect_resume_reproduces(PathMethod::kPseudoArclength, "shellindent_resume_arclength");
}

TEST(IndentationResume, NaturalResumedRunReproducesThePath) {
  expect_resume_reproduces(PathMethod::kNatural, "shellindent_resume_natural");
}

// Issue 7: the local approach alpha is one more unknown of the checkpoint.
TEST(IndentationResume, PseudoArclengthWithYangSunLocalLawReproducesThePath) {
  expect_resume_reproduces(PathMethod::kPseudoArclength, "shellindent_resume_yang_sun",
                           LocalContactModel::kYangSun);
}

}  // namespace
}  // namespace si
