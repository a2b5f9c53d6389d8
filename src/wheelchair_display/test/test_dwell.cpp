#include <gtest/gtest.h>
#include <wheelchair_display/dwell.h>

namespace wheelchair_display {

TEST(Dwell, RestingOnATargetForTheDwellTimeChoosesItOnce) {
  DwellTimer dwell(1.5, 20.0);
  EXPECT_FALSE(dwell.update(0.0, {100, 100}, 3).fired);
  const auto half = dwell.update(0.75, {102, 99}, 3);
  EXPECT_NEAR(half.progress, 0.5, 1e-9);
  EXPECT_FALSE(half.fired);
  const auto done = dwell.update(1.5, {101, 101}, 3);
  EXPECT_TRUE(done.fired);
  EXPECT_EQ(done.target, 3);
  // Resting on: no repeat.
  EXPECT_FALSE(dwell.update(4.0, {101, 101}, 3).fired);
  EXPECT_EQ(dwell.update(4.0, {101, 101}, 3).progress, 0.0);
}

TEST(Dwell, LeavingAndComingBackChoosesAgain) {
  DwellTimer dwell(1.0, 20.0);
  dwell.update(0.0, {0, 0}, 1);
  ASSERT_TRUE(dwell.update(1.0, {0, 0}, 1).fired);
  dwell.update(1.2, {300, 0}, kNoTarget);
  dwell.update(1.4, {0, 0}, 1);
  EXPECT_FALSE(dwell.update(2.3, {0, 0}, 1).fired);
  EXPECT_TRUE(dwell.update(2.4, {0, 0}, 1).fired);
}

TEST(Dwell, MovingToAnotherTargetOrBeyondTheRadiusStartsAgain) {
  DwellTimer dwell(1.0, 20.0);
  dwell.update(0.0, {0, 0}, 1);
  dwell.update(0.9, {5, 5}, 2);  // another target
  EXPECT_FALSE(dwell.update(1.5, {5, 5}, 2).fired);
  EXPECT_TRUE(dwell.update(1.9, {5, 5}, 2).fired);
  dwell.update(2.0, {100, 100}, 4);
  dwell.update(2.9, {150, 100}, 4);  // same target, but 50 px away: a new dwell
  EXPECT_FALSE(dwell.update(3.5, {150, 100}, 4).fired);
  EXPECT_TRUE(dwell.update(3.9, {150, 100}, 4).fired);
}

TEST(Dwell, AfterAChoiceNothingIsChosenUntilThePointerMoves) {
  DwellTimer dwell(1.0, 20.0);
  dwell.rest({100, 100});  // a room opened under the pointer: now a place lies there
  for (double t = 0; t < 5; t += 0.1) EXPECT_FALSE(dwell.update(t, {105, 98}, 7).fired);
  dwell.update(5.0, {160, 100}, 7);  // moved away (and still on the place): a new dwell
  EXPECT_FALSE(dwell.update(5.9, {160, 100}, 7).fired);
  EXPECT_TRUE(dwell.update(6.0, {160, 100}, 7).fired);
}

TEST(Dwell, NothingToChooseNeverFires) {
  DwellTimer dwell(0.5, 20.0);
  for (double t = 0; t < 5; t += 0.1) EXPECT_FALSE(dwell.update(t, {1, 1}, kNoTarget).fired);
  EXPECT_EQ(dwell.update(5.0, {1, 1}, kNoTarget).progress, 0.0);
}

}  // namespace wheelchair_display
