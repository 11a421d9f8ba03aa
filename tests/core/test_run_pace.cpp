// The progress line's time left (core/run_pace.hpp, app/progress_line.hpp) comes from the pace of
// the points this process ran: a resumed run's clock starts at its checkpoint, not at depth 0.
#include "core/run_pace.hpp"

#include <gtest/gtest.h>

namespace si {
namespace {

TEST(RunPace, FreshRunExtrapolatesItsPaceFromTheStart) {
  RunPace pace;
  pace.add(0.0, 0.5);
  EXPECT_FALSE(pace.remaining(10.0).has_value());  // one point: no pace yet
  pace.add(1.0, 10.5);
  ASSERT_TRUE(pace.remaining(10.0).has_value());
  EXPECT_DOUBLE_EQ(*pace.remaining(10.0), 90.0);  // 10 s per mm, 9 mm to go
}

// The 1e6-unknown cap resumed at 8.19 mm (docs/performance.md): its first point at 8.3605 mm
// after 136.5 s, the next at 8.5343 mm after 189.9 s. The time left is the pace between them,
// 53.4 s per 0.1738 mm, over the 1.4657 mm to go; the depth from 0 over this process's clock
// said 27 s.
TEST(RunPace, ResumedRunTakesThePaceSinceItsFirstPoint) {
  RunPace pace;
  pace.add(8.3605, 136.5);
  EXPECT_FALSE(pace.remaining(10.0).has_value());
  pace.add(8.5343, 189.9);
  ASSERT_TRUE(pace.remaining(10.0).has_value());
  EXPECT_NEAR(*pace.remaining(10.0), 53.4 / 0.1738 * 1.4657, 1e-9);
}

// The first step from first touch builds the contact set and the preconditioner from nothing:
// on the 1e6-unknown cap (docs/performance.md) 568 s for 0.0996 mm, then 55.3 s for 0.0497 mm.
// From the third point on the pace leaves it out.
TEST(RunPace, TheFirstStepIsLeftOutOnceThereIsAnother) {
  RunPace pace;
  pace.add(0.0, 75.4);
  pace.add(0.0996, 643.1);
  EXPECT_NEAR(*pace.remaining(10.0), 567.7 / 0.0996 * 9.9004, 1e-6);  // all it has
  pace.add(0.1493, 698.4);
  EXPECT_NEAR(*pace.remaining(10.0), 55.3 / 0.0497 * 9.8507, 1e-6);
}

// The pace of the last kWindowSteps steps: twenty steps at 1 s per 0.1 mm, then ten at 3 s.
TEST(RunPace, FollowsThePaceOfTheLastSteps) {
  RunPace pace;
  double depth = 0.0, seconds = 0.0;
  pace.add(depth, seconds);
  for (int i = 0; i < 20; ++i) pace.add(depth += 0.1, seconds += 1.0);
  EXPECT_NEAR(*pace.remaining(10.0), 10.0 * (10.0 - depth), 1e-9);
  for (int i = 0; i < 10; ++i) pace.add(depth += 0.1, seconds += 3.0);
  EXPECT_NEAR(*pace.remaining(10.0), 30.0 * (10.0 - depth), 1e-9);
  // Halfway into the change the window holds both paces, in proportion.
  RunPace mixed;
  depth = seconds = 0.0;
  mixed.add(depth, seconds);
  for (int i = 0; i < 20; ++i) mixed.add(depth += 0.1, seconds += 1.0);
  for (int i = 0; i < 4; ++i) mixed.add(depth += 0.1, seconds += 3.0);
  EXPECT_NEAR(*mixed.remaining(10.0), (4 * 3.0 + 4 * 1.0) / 0.8 * (10.0 - depth), 1e-9);
}

// No progress, no time left: a path that snaps back behind its first point, or is at its end.
TEST(RunPace, NoEstimateWithoutProgressOrAtTheEnd) {
  RunPace pace;
  pace.add(2.0, 1.0);
  pace.add(1.5, 3.0);
  EXPECT_FALSE(pace.remaining(10.0).has_value());
  pace.add(10.0, 9.0);
  EXPECT_FALSE(pace.remaining(10.0).has_value());
}

}  // namespace
}  // namespace si
