// The protective field: its length against a simulated jerk-limited stop, its inverse, its
// keys, and the supervisor stopping, slowing and limiting the speed with it.
#include <wheelchair_safety/protective_field.h>
#include <wheelchair_safety/safety_supervisor.h>

#include "safety_fixtures.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>

using namespace wheelchair_safety;
using wheelchair_core::LaserScan2D;
using wheelchair_core::OccupancyMap;
using wheelchair_core::Pose2D;
using wheelchair_safety_test::corridorMap;
using wheelchair_safety_test::personAt;
using wheelchair_safety_test::straightPath;

namespace {

/// Distance a chair at speed v covers until rest, integrated in 1 ms steps: it keeps
/// accelerating at drive_accel for the reaction time, then its deceleration ramps at brake_jerk
/// to -brake_decel and holds there until rest (the controller's controlled stop).
double simulatedStop(const ProtectiveField& f, double v) {
  const double dt = 1e-4;
  double s = 0.0, a = f.drive_accel;
  for (double t = 0.0; t < f.reaction_time; t += dt) s += v * dt, v += a * dt;
  while (v > 0.0) {
    a = std::max(-f.brake_decel, a - f.brake_jerk * dt);
    s += v * dt;
    v += a * dt;
  }
  return s;
}

/// Healthy data at t = 10 s, chair at (2, 2) heading +x on the path, driving at `speed`.
SafetySupervisor driving(double speed) {
  SafetySupervisor s;
  s.onMap(corridorMap(false));
  s.onPath(straightPath(9.5));
  s.onLocalization(10.0, true, Eigen::Matrix3d::Identity() * 1e-3, "");
  s.onPose(10.0, Pose2D{2.0, 2.0, 0.0});
  s.onSpeed(10.0, speed);
  s.onScan(10.0, {});
  return s;
}

/// A 180 degree scan of 361 beams, range_max `range`, every beam without a return.
LaserScan2D openScan(double range) {
  LaserScan2D scan;
  scan.angle_min = -M_PI / 2;
  scan.angle_max = M_PI / 2;
  scan.angle_increment = M_PI / 360;
  scan.range_min = 0.05;
  scan.range_max = range;
  scan.ranges.assign(361, INFINITY);
  return scan;
}

const Pose2D kLaser{2.28, 2.0, 0.0};  // the chair at (2, 2), laser 0.28 m ahead of the axle

}  // namespace

TEST(ProtectiveField, StopZoneCoversTheSimulatedStopFromEachSpeedWithItsMargin) {
  const ProtectiveField f;
  for (double v : {0.02, 0.1, 0.3, 0.8, 1.2, 1.5}) {
    const double needed = simulatedStop(f, v) + f.margin;
    EXPECT_GE(f.stopDistance(v) + 1e-3, needed) << v;  // 1e-3: the integration's own error
    EXPECT_LE(f.stopDistance(v), needed + 1e-2) << v << ": not needlessly long";
  }
  EXPECT_GT(f.stopDistance(0.0), f.margin) << "at rest it may be about to drive off";
}

TEST(ProtectiveField, StopZoneAtTheChairsTopSpeedIsLongerThanTheIssuesFigure) {
  // Issue 20: at 1.5 m/s the stop needs v^2/2a + v t_detect ~ 2.7 m; the fixed field was 1.2 m.
  const ProtectiveField f;
  EXPECT_GT(f.stopDistance(1.5), 1.5 * 1.5 / 1.0 + 1.5 * f.reaction_time + f.margin);
}

TEST(ProtectiveField, MaxStoppableSpeedIsTheInverseOfTheStopZone) {
  const ProtectiveField f;
  for (double v : {0.1, 0.5, 1.0, 1.5, 2.0})
    EXPECT_NEAR(f.maxStoppableSpeed(f.stopDistance(v)), v, 1e-9);
  for (double v : {0.01, 0.05}) EXPECT_NEAR(f.maxStoppableSpeed(f.stopDistance(v)), v, 1e-9);
  EXPECT_EQ(f.maxStoppableSpeed(f.stopDistance(0.0)), 0.0);
  EXPECT_EQ(f.maxStoppableSpeed(-1.0), 0.0);
}

TEST(ProtectiveField, EveryKeyIsReadAndABadValueIsRefused) {
  const auto f = wheelchair_core::loadConfig<ProtectiveField>(
      wheelchair_core::YamlParameterSource(
          YAML::Load("{field: {reaction_time: 0.2, brake_decel: 0.7, brake_jerk: 2, "
                     "drive_accel: 0.3, margin: 0.25, front_offset: 0.4, slowdown_length: 3, "
                     "view_tolerance: 0.2}}"),
          "test.yaml"),
      readProtectiveField);
  EXPECT_DOUBLE_EQ(f.reaction_time, 0.2);
  EXPECT_DOUBLE_EQ(f.brake_decel, 0.7);
  EXPECT_DOUBLE_EQ(f.brake_jerk, 2.0);
  EXPECT_DOUBLE_EQ(f.drive_accel, 0.3);
  EXPECT_DOUBLE_EQ(f.margin, 0.25);
  EXPECT_DOUBLE_EQ(f.front_offset, 0.4);
  EXPECT_DOUBLE_EQ(f.slowdown_length, 3.0);
  EXPECT_DOUBLE_EQ(f.view_tolerance, 0.2);
  ProtectiveField bad;
  bad.brake_decel = 0.0;
  EXPECT_NE(bad.validate().find("field/brake_decel"), std::string::npos) << bad.validate();
}

TEST(ProtectiveFieldSupervisor, PersonBeyondTheFixedFieldStopsAtTopSpeedButNotAtRest) {
  // 2.75 m ahead of the axle: outside the old fixed 1.2 m, inside the 1.5 m/s zone (3.84 m).
  SafetySupervisor at_rest = driving(0.0);
  at_rest.onScan(10.05, personAt(4.9, 2.0));
  EXPECT_FALSE(at_rest.check(10.1).stop) << at_rest.check(10.1).detail;

  SafetySupervisor fast = driving(1.5);
  EXPECT_NEAR(fast.stopExtent(), 0.30 + ProtectiveField().stopDistance(1.5), 1e-12);
  fast.onScan(10.05, personAt(4.9, 2.0));
  const SafetyVerdict v = fast.check(10.1);
  EXPECT_TRUE(v.stop);
  EXPECT_EQ(v.reason, StopReason::kUnexpectedObstacle);
  EXPECT_NE(v.detail.find("at 1.50 m/s"), std::string::npos) << v.detail;
  EXPECT_EQ(fast.speedLimit().speed, 0.0) << "a stop holds the speed at 0";
}

TEST(ProtectiveFieldSupervisor, PersonInTheSlowDownZoneLimitsTheSpeedSoTheChairCanStop) {
  SafetySupervisor s = driving(0.8);    // stop zone 0.3 + 1.38 m from the axle
  s.onScan(10.05, personAt(5.0, 2.0));  // nearest returns 2.85 m from the axle
  EXPECT_FALSE(s.check(10.1).stop) << s.check(10.1).detail;
  const ProtectiveField f;
  // The third-nearest return (min_obstacle_returns 3) is at 5.0 - 0.15 cos(0.2) - 2.0.
  const double s_third = 3.0 - 0.15 * std::cos(0.2);
  EXPECT_NEAR(s.speedLimit().speed, f.maxStoppableSpeed(s_third - f.front_offset), 1e-6);
  EXPECT_LT(s.speedLimit().speed, 1.5);
  EXPECT_GT(s.speedLimit().speed, 0.8);

  s.onScan(10.15, personAt(9.5, 2.0));  // beyond the slow-down zone: no limit
  EXPECT_EQ(s.speedLimit().speed, INFINITY);
  s.onScan(10.2, {Eigen::Vector2d(5.0, 2.0), Eigen::Vector2d(5.1, 2.0)});  // two stray returns
  EXPECT_EQ(s.speedLimit().speed, INFINITY);
}

TEST(ProtectiveFieldSupervisor, WhatTheLaserCannotSeeLimitsTheSpeed) {
  const ProtectiveField f;
  SafetySupervisor s = driving(0.5);
  s.onLaserView(openScan(30.0), kLaser);
  EXPECT_EQ(s.speedLimit().speed, INFINITY) << "sees the whole field: no limit";

  // Range: a 2 m scanner sees the path to 2.28 m from the axle.
  s.onLaserView(openScan(2.0), kLaser);
  EXPECT_NEAR(s.speedLimit().speed, f.maxStoppableSpeed(2.28 - f.front_offset), 0.05);

  // Occlusion: a return 1.2 m straight ahead hides the rest of the path.
  LaserScan2D wall = openScan(30.0);
  for (int i = 170; i <= 190; ++i) wall.ranges[i] = 1.2f;
  s.onLaserView(wall, kLaser);
  EXPECT_NEAR(s.speedLimit().speed,
              f.maxStoppableSpeed(0.28 + 1.2 + f.view_tolerance - f.front_offset), 0.05);

  // Field of view: a 60 degree scanner does not see a path that turns away to the left.
  SafetySupervisor turning = driving(0.5);
  std::vector<Pose2D> turn;
  for (double x = 2.0; x <= 3.0; x += 0.05) turn.push_back({x, 2.0, 0.0});
  for (double y = 2.05; y <= 6.0; y += 0.05) turn.push_back({3.0, y, M_PI / 2});
  turning.onPath(turn);
  LaserScan2D narrow = openScan(30.0);
  narrow.angle_min = -M_PI / 6;
  narrow.angle_max = M_PI / 6;
  narrow.angle_increment = M_PI / 180;
  narrow.ranges.assign(61, INFINITY);
  turning.onLaserView(narrow, kLaser);
  // The path leaves the +-30 degree view at (3.0, 2.0 + 0.72 tan 30deg): 1.0 + 0.42 m along it.
  EXPECT_NEAR(turning.speedLimit().speed,
              f.maxStoppableSpeed(1.0 + 0.72 * std::tan(M_PI / 6) - f.front_offset), 0.05);

  // Unusable beams see nothing.
  LaserScan2D blind = openScan(30.0);
  blind.ranges.assign(361, NAN);
  s.onLaserView(blind, kLaser);
  EXPECT_EQ(s.speedLimit().speed, 0.0);
}

TEST(ProtectiveFieldSupervisor, APathVertexJustBehindTheChairDoesNotBlindIt) {
  // The path's nearest vertex lies behind the axle and beside it (the chair 1 cm past it,
  // 3 cm off): the polyline runs back under the chair, where the laser cannot look.
  SafetySupervisor s = driving(0.5);
  s.onPose(10.0, Pose2D{2.06, 2.03, 0.0});
  s.onLaserView(openScan(30.0), Pose2D{2.34, 2.03, 0.0});
  EXPECT_EQ(s.speedLimit().speed, INFINITY) << s.speedLimit().detail;
  // The laser's pose 4 cm ahead of where the chair's says (two tf stamps while driving).
  s.onLaserView(openScan(30.0), Pose2D{2.38, 2.03, 0.0});
  EXPECT_EQ(s.speedLimit().speed, INFINITY) << s.speedLimit().detail;
}

TEST(ProtectiveFieldSupervisor, AStraightPathWithFewVerticesIsSeenFromItsMiddle) {
  // A planner's straight path may have vertices metres apart: the path ahead starts where the
  // chair is along it, not at the vertex behind.
  SafetySupervisor s = driving(0.5);
  s.onPath({{1.0, 2.0, 0.0}, {9.5, 2.0, 0.0}});
  s.onPose(10.0, Pose2D{3.0, 2.0, 0.0});
  s.onLaserView(openScan(30.0), Pose2D{3.28, 2.0, 0.0});
  EXPECT_EQ(s.speedLimit().speed, INFINITY) << s.speedLimit().detail;
  s.onScan(10.05, personAt(3.8, 2.0));  // 0.65 m ahead of the axle: stop
  EXPECT_EQ(s.check(10.1).reason, StopReason::kUnexpectedObstacle);
}
