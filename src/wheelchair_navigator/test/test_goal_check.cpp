// The goal check against the geometry of the test room: the point in a wall or in furniture,
// outside the map, the body not fitting (a pocket narrower than the chair, furniture within
// the tail's reach), and free goals with room.
#include <wheelchair_navigator/goal_check.h>

#include "test_world.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wheelchair_navigator {
namespace {

using wheelchair_navigator_test::chairFootprint;
using wheelchair_navigator_test::kHalfWidth;
using wheelchair_navigator_test::testRoom;

class GoalCheckTest : public ::testing::Test {
 protected:
  GoalCheck check{testRoom(), chairFootprint(), kHalfWidth};
};

TEST_F(GoalCheckTest, APointInAWallOrInFurnitureIsInAnObstacle) {
  for (const wheelchair_core::Pose2D& goal :
       {wheelchair_core::Pose2D{7.5, 1.5, 0.0}, {0.05, 2.5, 0.0}, {5.0, 5.5, 0.0}}) {
    const auto refusal = check.check(goal, 0.0);
    ASSERT_TRUE(refusal);
    EXPECT_EQ(refusal->reason, Reason::kGoalInObstacle) << refusal->detail;
  }
}

TEST_F(GoalCheckTest, OutsideTheMapIsOutside) {
  const auto refusal = check.check({-2.0, -3.0, 0.0}, 0.0);
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->reason, Reason::kGoalOutsideMap);
}

TEST_F(GoalCheckTest, AFreePointWhereTheBodyOverlapsIsNoRoom) {
  // In the 0.4 m pocket (free cell, 0.2 m to the walls): the 0.62 m wide body does not fit.
  auto refusal = check.check({2.2, 5.5, M_PI / 2}, 0.0);
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->reason, Reason::kGoalNoRoom) << refusal->detail;
  // 0.2 m beside the block with the tail swung over it (the axle 0.5 m from it, facing away).
  refusal = check.check({7.5, 2.5, M_PI / 2}, 0.0);
  ASSERT_TRUE(refusal);
  EXPECT_EQ(refusal->reason, Reason::kGoalNoRoom) << refusal->detail;
}

TEST_F(GoalCheckTest, AGoalWithRoomIsAccepted) {
  EXPECT_FALSE(check.check({5.0, 3.0, 0.0}, 0.0));
  EXPECT_FALSE(check.check({7.5, 3.5, M_PI / 2}, 0.05)) << "the body ends 0.7 m from the block";
  // 0.05 m short of the wall with the tail: fits at 0, not with 0.10 m asked for.
  const wheelchair_core::Pose2D near_wall{0.1 + 0.8 + 0.05, 2.5, 0.0};
  EXPECT_FALSE(check.check(near_wall, 0.0));
  const auto tight = check.check(near_wall, 0.10);
  ASSERT_TRUE(tight);
  EXPECT_EQ(tight->reason, Reason::kGoalNoRoom);
}

}  // namespace
}  // namespace wheelchair_navigator
