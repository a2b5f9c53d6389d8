// Each stop condition of the supervisor, its latch, and what must not stop the chair.
#include <wheelchair_safety/safety_supervisor.h>

#include "safety_fixtures.h"

#include <gtest/gtest.h>

using namespace wheelchair_safety;
using wheelchair_core::OccupancyMap;
using wheelchair_core::Pose2D;
using wheelchair_safety_test::corridorMap;
using wheelchair_safety_test::personAt;
using wheelchair_safety_test::straightPath;

namespace {

/// A supervisor fed healthy data at time t, chair at (2, 2) heading +x on the path.
SafetySupervisor healthy(double t = 10.0) {
  SafetySupervisor s;
  s.onMap(corridorMap());
  s.onPath(straightPath());
  s.onLocalization(t, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  s.onPose(t, Pose2D{2.0, 2.0, 0.0});
  s.onScan(t, {});
  return s;
}

}  // namespace

TEST(SafetySupervisor, HealthyDataDoesNotStop) {
  SafetySupervisor s = healthy();
  EXPECT_FALSE(s.check(10.1).stop) << s.check(10.1).detail;
}

TEST(SafetySupervisor, NoDataYetStopsUntilTheDataArrives) {
  SafetySupervisor s;
  EXPECT_EQ(s.check(0.0).reason, StopReason::kNoData);
  s.onLocalization(0.1, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  s.onPose(0.1, Pose2D{2.0, 2.0, 0.0});
  s.onScan(0.1, {});
  EXPECT_FALSE(s.check(0.2).stop) << s.check(0.2).detail;
}

TEST(SafetySupervisor, LaserSilentFor300msStops) {
  SafetySupervisor s = healthy();
  s.onPose(10.29, Pose2D{2.0, 2.0, 0.0});
  s.onLocalization(10.29, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  EXPECT_FALSE(s.check(10.29).stop);
  const SafetyVerdict v = s.check(10.31);
  EXPECT_EQ(v.reason, StopReason::kLaserSilent);
  EXPECT_NE(v.detail.find("0.31 s"), std::string::npos) << v.detail;
  EXPECT_NEAR(v.value, 0.31, 1e-9);  // the numbers behind the verdict: the age and its limit
  EXPECT_DOUBLE_EQ(v.limit, SafetyLimits().scan_timeout);
}

TEST(SafetySupervisor, StalePoseStops) {
  SafetySupervisor s = healthy();
  s.onScan(10.35, {});
  s.onPose(10.35, Pose2D{NAN, 2.0, 0.0});  // non-finite: not a refresh
  EXPECT_EQ(s.check(10.35).reason, StopReason::kPoseStale);
}

TEST(SafetySupervisor, LostLocalizationStopsWithTheLocalizersReason) {
  SafetySupervisor s = healthy();
  s.onLocalization(10.05, false, Eigen::Matrix3d::Identity() * 1e-3, "two clusters");
  const SafetyVerdict v = s.check(10.1);
  EXPECT_EQ(v.reason, StopReason::kLocalizationLost);
  EXPECT_EQ(v.detail, "two clusters");
}

TEST(SafetySupervisor, GrowingCovarianceStops) {
  SafetySupervisor s = healthy();
  Eigen::Matrix3d cov = Eigen::Matrix3d::Identity() * 1e-3;
  cov(1, 1) = 0.21 * 0.21;
  s.onLocalization(10.05, true, cov, "");
  const SafetyVerdict v = s.check(10.1);
  EXPECT_EQ(v.reason, StopReason::kCovarianceTooLarge);
  EXPECT_NEAR(v.value, 0.21, 1e-9);  // the position std-dev against max_position_std
  EXPECT_DOUBLE_EQ(v.limit, SafetyLimits().max_position_std);
}

TEST(SafetySupervisor, DriverFaultThatPersistsStops) {
  SafetySupervisor s = healthy();
  const double grace = SafetyLimits().driver_fault_grace;
  s.onDriverStatus(10.0, true, "motor controller heartbeat lost");
  EXPECT_FALSE(s.check(10.0 + 0.5 * grace).stop);  // the driver brakes by itself meanwhile
  s.onScan(10.0 + grace, {});
  s.onPose(10.0 + grace, Pose2D{2.0, 2.0, 0.0});
  const SafetyVerdict v = s.check(10.0 + grace + 0.01);
  EXPECT_EQ(v.reason, StopReason::kDriverFault);
  EXPECT_EQ(v.detail, "motor controller heartbeat lost");
}

TEST(SafetySupervisor, DriverFaultThatClearsWithinTheGraceDoesNotStop) {
  SafetySupervisor s = healthy();
  const double grace = SafetyLimits().driver_fault_grace;
  s.onDriverStatus(10.0, true, "command_timeout");
  s.onDriverStatus(10.0 + 0.2 * grace, false, "driving");
  s.onDriverStatus(10.0 + 0.6 * grace, true, "command_timeout");  // the grace restarts
  s.onScan(10.0 + grace, {});
  s.onPose(10.0 + grace, Pose2D{2.0, 2.0, 0.0});
  EXPECT_FALSE(s.check(10.0 + grace + 0.01).stop) << s.check(10.0 + grace + 0.01).detail;
}

// bench/navigation saw it: the rider's release reached the driver and the supervisor, and the
// supervisor latched again at once on the driver's stop reported before the release.
TEST(SafetySupervisor, TheRidersReleaseAlsoReleasesTheDriversStopItHeard) {
  SafetySupervisor s = healthy();
  const double grace = SafetyLimits().driver_fault_grace;
  s.onDriverStatus(10.0 - grace, true, "the chair's computer paused");  // a latched driver stop
  ASSERT_EQ(s.check(10.01).reason, StopReason::kDriverFault);
  s.onUserCommand(10.02);
  EXPECT_FALSE(s.check(10.03).stop) << s.check(10.03).detail;
  // The fault still holds: the driver reports it again after the release, and it stops again.
  s.onDriverStatus(10.04, true, "the motors report a fault");
  s.onScan(10.04 + grace, {});
  s.onPose(10.04 + grace, Pose2D{2.0, 2.0, 0.0});
  EXPECT_EQ(s.check(10.05 + grace).reason, StopReason::kDriverFault);
}

TEST(SafetySupervisor, PersonSteppingOntoThePathAheadStops) {
  SafetySupervisor s = healthy();
  s.onScan(10.05, personAt(2.9, 2.1));  // 0.9 m ahead, on the path
  const SafetyVerdict v = s.check(10.1);
  EXPECT_EQ(v.reason, StopReason::kUnexpectedObstacle);
  EXPECT_GE(v.value, v.limit);  // returns counted against min_obstacle_returns
  EXPECT_DOUBLE_EQ(v.limit, SafetyLimits().min_obstacle_returns);
}

TEST(SafetySupervisor, ThingsBesideOrFarAheadOrInTheMapDoNotStop) {
  SafetySupervisor s = healthy();
  s.onScan(10.05, personAt(2.9, 2.8));  // beside the corridor (0.8 m off the path)
  EXPECT_FALSE(s.check(10.1).stop);
  s.onScan(10.1, personAt(4.0, 2.0));  // 2 m ahead: beyond the stop distance
  EXPECT_FALSE(s.check(10.15).stop);
  s.onScan(10.15, {Eigen::Vector2d(2.8, 2.0), Eigen::Vector2d(2.9, 2.0)});  // two stray returns
  EXPECT_FALSE(s.check(10.2).stop);
  s.onPose(10.2, Pose2D{8.2, 2.0, 0.0});  // near the end, the mapped wall ahead
  s.onLocalization(10.2, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  s.onScan(10.2, personAt(9.0, 2.0));
  EXPECT_FALSE(s.check(10.25).stop) << s.check(10.25).detail;
}

TEST(SafetySupervisor, StopLatchesUntilTheRiderCommandsAgain) {
  SafetySupervisor s = healthy();
  s.onScan(10.05, personAt(2.9, 2.0));
  ASSERT_TRUE(s.check(10.1).stop);
  s.onScan(10.2, {});  // the person has gone: still stopped
  s.onPose(10.2, Pose2D{2.0, 2.0, 0.0});
  s.onLocalization(10.2, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  EXPECT_EQ(s.check(10.25).reason, StopReason::kUnexpectedObstacle);
  s.onUserCommand(10.3);
  EXPECT_FALSE(s.check(10.3).stop);
}

TEST(SafetySupervisor, UserStopWins) {
  SafetySupervisor s = healthy();
  s.onUserStop(10.05);
  EXPECT_EQ(s.check(10.1).reason, StopReason::kUserStop);
  s.onUserCommand(10.2);
  EXPECT_FALSE(s.check(10.2).stop);
}

// Mapping mode (require_localizer false): no localizer to wait for, SLAM's pose is the pose;
// the laser, the pose's age and the field ahead are still watched.
TEST(SafetySupervisor, WithoutALocalizerTheLaserPoseAndFieldStillStop) {
  SafetyLimits limits;
  limits.require_localizer = false;
  SafetySupervisor s(limits);
  s.onMap(corridorMap());
  s.onPath(straightPath());
  s.onPose(10.0, Pose2D{2.0, 2.0, 0.0});
  s.onScan(10.0, {});
  EXPECT_FALSE(s.check(10.1).stop) << s.check(10.1).detail;  // no localizer status ever
  s.onPose(10.2, Pose2D{2.0, 2.0, 0.0});
  s.onScan(10.2, personAt(2.9, 2.1));  // 0.9 m ahead, on the path
  EXPECT_EQ(s.check(10.25).reason, StopReason::kUnexpectedObstacle);

  SafetySupervisor silent(limits);
  silent.onPose(10.0, Pose2D{2.0, 2.0, 0.0});
  silent.onScan(10.0, {});
  silent.onPose(10.4, Pose2D{2.0, 2.0, 0.0});
  EXPECT_EQ(silent.check(10.4).reason, StopReason::kLaserSilent);

  SafetySupervisor required;  // the default: a localizer's status is required
  required.onPose(10.0, Pose2D{2.0, 2.0, 0.0});
  required.onScan(10.0, {});
  EXPECT_EQ(required.check(10.1).reason, StopReason::kNoData);
}
