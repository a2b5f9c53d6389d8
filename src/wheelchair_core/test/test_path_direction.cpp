// The one rule for the direction of motion along a plan (path_direction.h): yaw is the chair's
// heading, a step against it is reverse; the plan splits at the cusps.
#include <gtest/gtest.h>
#include <wheelchair_core/path_direction.h>

#include <cmath>

namespace wheelchair_core {
namespace {

/// Poses every `step` metres along a straight line from (x, y) in direction `motion`, the chair
/// facing `heading`.
std::vector<Pose2D> line(double x, double y, double motion, double heading, double length,
                         double step = 0.05) {
  std::vector<Pose2D> out;
  for (double s = 0.0; s <= length + 1e-9; s += step)
    out.push_back({x + s * std::cos(motion), y + s * std::sin(motion), heading});
  return out;
}

TEST(PathDirection, AForwardPlanWithTangentHeadingsIsOneForwardPiece) {
  const std::vector<Pose2D> path = line(0.0, 0.0, 0.3, 0.3, 2.0);
  const std::vector<PathPiece> pieces = splitAtCusps(path);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].direction, Direction::kForward);
  EXPECT_EQ(pieces[0].begin, 0u);
  EXPECT_EQ(pieces[0].end, path.size() - 1);
  EXPECT_EQ(cuspCount(path), 0u);
  EXPECT_DOUBLE_EQ(reversedLength(path), 0.0);
}

TEST(PathDirection, APlanFacingAgainstItsMotionIsReverse) {
  // Backing 1.5 m along -x while facing +x.
  const std::vector<Pose2D> path = line(2.0, 1.0, M_PI, 0.0, 1.5);
  const std::vector<PathPiece> pieces = splitAtCusps(path);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].direction, Direction::kReverse);
  EXPECT_NEAR(reversedLength(path), 1.5, 1e-9);
}

TEST(PathDirection, ABackUpThenDriveOffSplitsAtTheCuspWhichBothPiecesShare) {
  std::vector<Pose2D> path = line(0.0, 0.0, M_PI, 0.0, 1.0);  // back up 1 m facing +x
  const size_t cusp = path.size() - 1;
  const std::vector<Pose2D> ahead = line(-1.0, 0.0, 0.0, 0.0, 2.0);  // then 2 m forward
  path.insert(path.end(), ahead.begin() + 1, ahead.end());
  const std::vector<PathPiece> pieces = splitAtCusps(path);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].direction, Direction::kReverse);
  EXPECT_EQ(pieces[1].direction, Direction::kForward);
  EXPECT_EQ(pieces[0].end, cusp);
  EXPECT_EQ(pieces[1].begin, cusp);
  EXPECT_EQ(cuspCount(path), 1u);
  EXPECT_NEAR(reversedLength(path), 1.0, 1e-9);
}

TEST(PathDirection, SidewaysOrRepeatedStepsKeepTheDirectionAndAGoalYawDoesNotMakeACusp) {
  // A forward plan whose goal pose carries a heading 90 degrees off its last step (the chair
  // rotates there), with a repeated pose in the middle: still one forward piece.
  std::vector<Pose2D> path = line(0.0, 0.0, 0.0, 0.0, 1.0);
  path.insert(path.begin() + 5, path[5]);
  path.back().yaw = M_PI / 2;
  EXPECT_EQ(splitAtCusps(path).size(), 1u);
  EXPECT_EQ(stepDirection({0, 0, 0}, {0, 1, 0}, Direction::kReverse), Direction::kReverse);
  EXPECT_EQ(stepDirection({0, 0, 0}, {1e-6, 0, 0}, Direction::kReverse), Direction::kReverse);
  EXPECT_EQ(stepDirection({0, 0, 0}, {1, 0.2, 0}, Direction::kReverse), Direction::kForward);
  EXPECT_TRUE(splitAtCusps({}).empty());
  EXPECT_TRUE(splitAtCusps({{1, 2, 0}}).empty());
}

}  // namespace
}  // namespace wheelchair_core
