// The guard behind the chair (issue 24): no reverse motion while the rear laser is silent, a
// person stepping behind the chair while it backs up stops it, what is beside, far behind, in
// the map or behind a forward-driving chair does not.
#include <wheelchair_safety/safety_supervisor.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace wheelchair_safety;
using wheelchair_core::OccupancyMap;
using wheelchair_core::Pose2D;

namespace {

/// A 10 m x 4 m free corridor (5 cm cells) whose wall at x = 1 m is in the map.
OccupancyMap corridorMap() {
  OccupancyMap map;
  map.width = 200;
  map.height = 80;
  map.data.assign(map.width * map.height, wheelchair_core::kFree);
  for (int y = 0; y < map.height; ++y) map.at(20, y) = wheelchair_core::kOccupied;
  return map;
}

/// Backing up along y = 2 from x = 6 to x = 2.5, facing +x all the way (a reverse piece).
std::vector<Pose2D> reversePath() {
  std::vector<Pose2D> path;
  for (double x = 6.0; x >= 2.5 - 1e-9; x -= 0.05) path.push_back({x, 2.0, 0.0});
  return path;
}

/// Forwards from x = 2 to x = 5, then backing up to x = 4 (a cusp at x = 5).
std::vector<Pose2D> forwardThenReverse() {
  std::vector<Pose2D> path;
  for (double x = 2.0; x <= 5.0 + 1e-9; x += 0.05) path.push_back({x, 2.0, 0.0});
  for (double x = 4.95; x >= 4.0 - 1e-9; x -= 0.05) path.push_back({x, 2.0, 0.0});
  return path;
}

std::vector<Eigen::Vector2d> personAt(double x, double y) {
  std::vector<Eigen::Vector2d> returns;
  for (double a = -1.0; a <= 1.0; a += 0.2)
    returns.emplace_back(x + 0.15 * std::cos(a), y + 0.15 * std::sin(a));
  return returns;
}

/// Healthy front data at t, chair at `pose` on `path`; the rear laser as `rear` says.
SafetySupervisor fed(const std::vector<Pose2D>& path, const Pose2D& pose, bool rear,
                     double t = 10.0) {
  SafetySupervisor s;
  s.onMap(corridorMap());
  s.onPath(path);
  s.onLocalization(t, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  s.onPose(t, pose);
  s.onScan(t, {});
  if (rear) s.onRearScan(t, {});
  return s;
}

}  // namespace

TEST(RearGuard, NoReverseMotionWhileTheRearLaserIsSilent) {
  // Never a rear scan: backing up is refused at once.
  SafetySupervisor never = fed(reversePath(), {6.0, 2.0, 0.0}, false);
  const SafetyVerdict v = never.check(10.05);
  EXPECT_TRUE(v.stop);
  EXPECT_EQ(v.reason, StopReason::kRearSensorSilent);
  EXPECT_STREQ(describe(v.reason), "the sensor behind the chair is silent");
  // Live: no stop; silent for more than rear_scan_timeout: stop, with its age and limit.
  SafetySupervisor s = fed(reversePath(), {6.0, 2.0, 0.0}, true);
  EXPECT_FALSE(s.check(10.05).stop) << s.check(10.05).detail;
  s.onScan(10.3, {});
  s.onPose(10.3, {5.9, 2.0, 0.0});
  s.onLocalization(10.3, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  const SafetyVerdict silent = s.check(10.35);
  EXPECT_EQ(silent.reason, StopReason::kRearSensorSilent) << silent.detail;
  EXPECT_NEAR(silent.value, 0.35, 1e-9);
  EXPECT_DOUBLE_EQ(silent.limit, SafetyLimits().rear_scan_timeout);
}

TEST(RearGuard, AForwardPathNeedsNoRearLaser) {
  std::vector<Pose2D> forward;
  for (double x = 2.0; x <= 8.0; x += 0.05) forward.push_back({x, 2.0, 0.0});
  SafetySupervisor s = fed(forward, {2.0, 2.0, 0.0}, false);
  EXPECT_FALSE(s.check(10.05).stop) << s.check(10.05).detail;
}

TEST(RearGuard, ApproachingACuspTheRearLaserMustBeLiveBeforeTheChairBacksUp) {
  // 2.5 m before the cusp: not yet watched (stop_distance 1.2 m ahead).
  EXPECT_FALSE(fed(forwardThenReverse(), {2.5, 2.0, 0.0}, false).check(10.05).stop);
  // 0.8 m before it: the reverse piece is within the watched stretch.
  EXPECT_EQ(fed(forwardThenReverse(), {4.2, 2.0, 0.0}, false).check(10.05).reason,
            StopReason::kRearSensorSilent);
}

TEST(RearGuard, APersonSteppingBehindTheBackingChairStopsIt) {
  // The chair's rear is at x = 6 - 0.8 = 5.2; the person 0.3 m behind it, on the path.
  SafetySupervisor s = fed(reversePath(), {6.0, 2.0, 0.0}, true);
  s.onRearScan(10.05, personAt(4.9, 2.05));
  const SafetyVerdict v = s.check(10.1);
  EXPECT_EQ(v.reason, StopReason::kObstacleBehind) << v.detail;
  EXPECT_STREQ(describe(v.reason), "something is behind the chair");
  EXPECT_GE(v.value, v.limit);
  // Latched until the rider's command, as ahead.
  s.onRearScan(10.15, {});
  EXPECT_EQ(s.check(10.2).reason, StopReason::kObstacleBehind);
  s.onUserCommand(10.25);
  EXPECT_FALSE(s.check(10.25).stop);
}

// A short back-up (0.5 m): at its end the body's rear reaches 0.80 m beyond the axle's last
// position, so a person there is in the way although the path itself stops short of them.
TEST(RearGuard, APersonBehindTheEndOfAShortBackUpStopsIt) {
  std::vector<Pose2D> path;
  for (double x = 6.0; x >= 5.5 - 1e-9; x -= 0.05) path.push_back({x, 2.0, 0.0});
  SafetySupervisor s = fed(path, {6.0, 2.0, 0.0}, true);
  s.onRearScan(10.05, personAt(4.6, 2.0));  // 0.6 m behind the rear, 0.9 m beyond the path end
  const SafetyVerdict v = s.check(10.1);
  EXPECT_EQ(v.reason, StopReason::kObstacleBehind) << v.detail;
}

TEST(RearGuard, ThingsBesideFarBehindInTheMapOrBehindAForwardChairDoNotStop) {
  SafetySupervisor s = fed(reversePath(), {6.0, 2.0, 0.0}, true);
  s.onRearScan(10.05, personAt(4.9, 2.8));  // beside the corridor (0.8 m off the path)
  EXPECT_FALSE(s.check(10.1).stop) << s.check(10.1).detail;
  // 1.05 m behind the rear: beyond rear_stop_distance and the corridor's round end.
  s.onRearScan(10.1, personAt(4.0, 2.0));
  EXPECT_FALSE(s.check(10.15).stop) << s.check(10.15).detail;
  // Near the end of the reverse piece, the mapped wall at x = 1 behind the chair.
  s.onPose(10.15, {2.6, 2.0, 0.0});
  s.onLocalization(10.15, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  s.onScan(10.15, {});
  s.onRearScan(10.15, personAt(1.05, 2.0));
  EXPECT_FALSE(s.check(10.2).stop) << s.check(10.2).detail;
  // Driving forwards: a person right behind the chair is not on its way.
  std::vector<Pose2D> forward;
  for (double x = 6.0; x <= 9.0; x += 0.05) forward.push_back({x, 2.0, 0.0});
  SafetySupervisor f = fed(forward, {6.0, 2.0, 0.0}, true);
  f.onRearScan(10.05, personAt(4.9, 2.0));
  EXPECT_FALSE(f.check(10.1).stop) << f.check(10.1).detail;
}
