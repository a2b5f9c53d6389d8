// Reference poses of a replayed log: matched by identical readings (whatever the time base) or
// by stamp; the absolute error table against them.
#include <gtest/gtest.h>
#include <wheelchair_logs/reference.h>
#include <wheelchair_logs/splice.h>

#include <cmath>

namespace wheelchair_logs {
namespace {

using wheelchair_core::Pose2D;

LogScan scan(std::vector<float> ranges, double stamp, Pose2D pose) {
  LogScan s;
  s.scan.ranges = std::move(ranges);
  s.scan.stamp = stamp;
  s.laser_pose = pose;
  return s;
}

TEST(Reference, ScansAreMatchedByTheirReadingsInOrderEvenWhenRepeated) {
  // Relative stamps in the reference, absolute ones in the replayed log: only readings match.
  ReferenceTrajectory ref({scan({1, 2, INFINITY}, 1.0, {1, 0, 0}), scan({3, 4, 5}, 2.0, {2, 0, 0}),
                           scan({1, 2, INFINITY}, 3.0, {3, 0, 0})});
  const LogScan* a = ref.match(scan({1, 2, INFINITY}, 1e9 + 1, {}), ReferenceMatch::kReadings);
  ASSERT_NE(a, nullptr);
  EXPECT_DOUBLE_EQ(a->laser_pose.x, 1.0);
  const LogScan* b = ref.match(scan({3, 4, 5}, 1e9 + 2, {}), ReferenceMatch::kReadings);
  ASSERT_NE(b, nullptr);
  EXPECT_DOUBLE_EQ(b->laser_pose.x, 2.0);
  // The robot standing still repeats a scan: the next one after the last match is taken.
  const LogScan* c = ref.match(scan({1, 2, INFINITY}, 1e9 + 3, {}), ReferenceMatch::kReadings);
  ASSERT_NE(c, nullptr);
  EXPECT_DOUBLE_EQ(c->laser_pose.x, 3.0);
  EXPECT_EQ(ref.match(scan({1, 2, 3}, 1.0, {}), ReferenceMatch::kReadings), nullptr);
}

TEST(Reference, ByStampTheNearestWithinTheToleranceAfterTheOffset) {
  ReferenceTrajectory ref({scan({1}, 10.0, {1, 0, 0}), scan({2}, 10.2, {2, 0, 0})});
  const LogScan* a = ref.match(scan({9}, 1010.18, {}), ReferenceMatch::kStamp, -1000.0, 0.05);
  ASSERT_NE(a, nullptr);
  EXPECT_DOUBLE_EQ(a->laser_pose.x, 2.0);
  EXPECT_EQ(ref.match(scan({9}, 1010.1, {}), ReferenceMatch::kStamp, -1000.0, 0.05), nullptr);
  EXPECT_THROW(referenceMatchFromName("time"), std::invalid_argument);
}

TEST(Reference, PoseErrorsAreRmsMeanAndMaxOfPositionAndHeading) {
  const PoseErrors e = poseErrors({{{0.3, 0.4, 0.1}, {0, 0, 0}},       // 0.5 m, 0.1 rad
                                   {{1.0, 0.0, 3.1}, {1, 0, -3.1}}});  // 0 m, 2 pi - 6.2 rad
  EXPECT_EQ(e.count, 2u);
  EXPECT_NEAR(e.position_mean, 0.25, 1e-12);
  EXPECT_NEAR(e.position_rms, std::sqrt(0.125), 1e-12);
  EXPECT_NEAR(e.position_max, 0.5, 1e-12);
  const double wrap = 2 * M_PI - 6.2;
  EXPECT_NEAR(e.heading_max, std::max(0.1, wrap), 1e-12);
  EXPECT_NEAR(e.heading_mean, (0.1 + wrap) / 2, 1e-12);
}

}  // namespace
}  // namespace wheelchair_logs

namespace wheelchair_logs {
namespace {

// The spliced drive continues the odometry of the cut scan with the increments of the part it
// jumps to: odometry sees no jump, the scans (and their reference poses) do.
TEST(Splice, TheOdometryContinuesAcrossTheJumpWithTheLaterPartsIncrements) {
  std::vector<LogScan> log;
  for (int i = 0; i < 6; ++i) {
    LogScan s;
    s.scan.stamp = i;
    s.odom_pose = {1.0 * i, 0.5 * i, 0.1 * i};
    s.laser_pose = {10.0 + i, 0, 0};
    log.push_back(s);
  }
  const auto out = spliceKidnapping(log, 1, 4);
  ASSERT_EQ(out.size(), 4u);  // scans 0, 1, 4, 5
  EXPECT_DOUBLE_EQ(out[2].laser_pose.x, 14.0);
  EXPECT_NEAR(out[2].odom_pose.x, log[1].odom_pose.x, 1e-12) << "no jump in odometry";
  EXPECT_NEAR(out[2].odom_pose.yaw, log[1].odom_pose.yaw, 1e-12);
  const auto step = wheelchair_core::between(out[2].odom_pose, out[3].odom_pose);
  const auto expected = wheelchair_core::between(log[4].odom_pose, log[5].odom_pose);
  EXPECT_NEAR(step.x, expected.x, 1e-12);
  EXPECT_NEAR(step.y, expected.y, 1e-12);
  EXPECT_NEAR(step.yaw, expected.yaw, 1e-12);
  EXPECT_GT(out[2].scan.stamp, out[1].scan.stamp);
  EXPECT_THROW(spliceKidnapping(log, 1, 6), std::invalid_argument);
}

}  // namespace
}  // namespace wheelchair_logs
