// Wheel-encoder odometry: systematic errors as configured, random drift with the
// configured statistics, and agreement with the ground truth when error-free.
#include <wheelchair_sim/simulated_chair.h>
#include <wheelchair_sim/wheel_odometry.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wheelchair_sim {
namespace {

SimParams noErrors() {
  SimParams p;
  p.odom_radius_error_left = p.odom_radius_error_right = p.odom_track_error = 0.0;
  p.odom_noise = 0.0;
  return p;
}

/// Feeds `steps` equal encoder increments that roll each wheel's contact by (d_r, d_l) [m].
void roll(WheelOdometry& odo, const wheelchair_description::ChairParams& c, double d_r, double d_l,
          int steps) {
  Eigen::Vector2d psi = Eigen::Vector2d::Zero();
  odo.reset(wheelchair_core::Pose2D(), psi);
  for (int k = 1; k <= steps; ++k) {
    psi = Eigen::Vector2d(d_r, d_l) * (double(k) / steps) / c.wheel_radius;
    odo.update(psi, 0.02);
  }
}

TEST(Odometry, RadiusErrorScalesTheDistance) {
  const auto chair = test::chair();
  SimParams p = noErrors();
  p.odom_radius_error_right = p.odom_radius_error_left = 0.02;
  WheelOdometry odo(chair, p, 1);
  roll(odo, chair, 4.0, 4.0, 200);
  EXPECT_NEAR(odo.pose().x, 4.0 * 1.02, 1e-9);
  EXPECT_NEAR(odo.pose().y, 0.0, 1e-12);
}

TEST(Odometry, UnequalRadiiCurveAStraightDrive) {
  const auto chair = test::chair();
  SimParams p = noErrors();
  p.odom_radius_error_right = 0.01;
  WheelOdometry odo(chair, p, 1);
  roll(odo, chair, 5.0, 5.0, 500);
  EXPECT_NEAR(odo.pose().yaw, 0.5 * 5.0 * 0.01 / chair.half_track, 1e-9);
}

TEST(Odometry, TrackErrorScalesTheTurn) {
  const auto chair = test::chair();
  SimParams p = noErrors();
  p.odom_track_error = 0.05;
  WheelOdometry odo(chair, p, 1);
  const double arc = chair.half_track * M_PI / 2;  // a quarter turn in place
  roll(odo, chair, arc, -arc, 100);
  EXPECT_NEAR(odo.pose().yaw, M_PI / 2 / 1.05, 1e-9);
  EXPECT_NEAR(odo.pose().position().norm(), 0.0, 1e-12);
}

/// Sample mean and standard deviation of the final (distance, heading) errors of `runs`
/// straight drives of `distance` metres.
void driftStatistics(double noise, double distance, int runs, Eigen::Vector2d& mean,
                     Eigen::Vector2d& stddev) {
  const auto chair = test::chair();
  SimParams p = noErrors();
  p.odom_noise = noise;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero(), sum2 = Eigen::Vector2d::Zero();
  for (int run = 0; run < runs; ++run) {
    WheelOdometry odo(chair, p, 1000 + run);
    roll(odo, chair, distance, distance, 100);
    const Eigen::Vector2d e(odo.pose().x - distance, odo.pose().yaw);
    sum += e;
    sum2 += e.cwiseProduct(e);
  }
  mean = sum / runs;
  stddev = (sum2 / runs - mean.cwiseProduct(mean)).cwiseSqrt();
}

// Each wheel's travel error after D metres is N(0, k^2 D): the heading error has variance
// k^2 D / (2 b^2) exactly, the distance error k^2 D / 2 (to first order: heading errors also
// shorten the drive along x, by k^2 D^2 / (8 b^2) on average, negligible for small k).
TEST(Odometry, RandomDriftMatchesTheConfiguredNoiseOverManyRuns) {
  const double b = test::chair().half_track, distance = 5.0;
  const int runs = 600;  // sample std: relative spread 1/sqrt(2 * 600) = 2.9 %; allow 4 sigma
  Eigen::Vector2d mean, stddev;
  driftStatistics(0.02, distance, runs, mean, stddev);
  const double expect_h = 0.02 * std::sqrt(distance / 2) / b;
  EXPECT_NEAR(stddev(1), expect_h, 0.12 * expect_h);
  EXPECT_NEAR(mean(1), 0.0, 4 * expect_h / std::sqrt(runs));
  driftStatistics(0.002, distance, runs, mean, stddev);
  const double expect_d = 0.002 * std::sqrt(distance / 2);
  EXPECT_NEAR(stddev(0), expect_d, 0.12 * expect_d);
  EXPECT_NEAR(mean(0), 0.0, 4 * expect_d / std::sqrt(runs));
}

TEST(Odometry, ErrorFreeOdometryFollowsTheGroundTruthOnACurve) {
  const auto chair = test::chair();
  SimParams p = noErrors();
  p.rolling_resistance = false;
  SimulatedChair sim(chair, p, nullptr);
  sim.simulator().applyWheelTorques(6.0, 2.0, false);
  for (int i = 0; i < 600; ++i) sim.advance(0.01);
  ASSERT_GT(sim.simulator().pose().position().norm(), 1.0);
  ASSERT_GT(std::abs(sim.simulator().pose().y), 0.3);  // a curve, not a line
  const wheelchair_core::Pose2D odo = sim.odometry().pose(), truth = sim.simulator().pose();
  EXPECT_LT((odo.position() - truth.position()).norm(), 2e-3);
  EXPECT_NEAR(std::remainder(odo.yaw - truth.yaw, 2 * M_PI), 0.0, 1e-3);
  EXPECT_NEAR(sim.odometry().velocity().v, sim.simulator().velocity().v, 0.02);
}

TEST(Odometry, TeleportIsInvisibleToOdometryButResetRestartsIt) {
  const auto chair = test::chair();
  SimulatedChair sim(chair, noErrors(), nullptr);
  ASSERT_TRUE(sim.teleport({5.0, 5.0, 1.0}));
  EXPECT_EQ(test::asVector(sim.odometry().pose()), Eigen::Vector3d::Zero());
  sim.simulator().applyWheelTorques(10.0, 10.0, false);
  for (int i = 0; i < 100; ++i) sim.advance(0.01);
  ASSERT_GT(sim.odometry().pose().x, 0.1);
  ASSERT_TRUE(sim.reset({1.0, 1.0, 0.0}));
  EXPECT_EQ(test::asVector(sim.odometry().pose()), Eigen::Vector3d::Zero());
  EXPECT_EQ(test::asVector(sim.simulator().velocity()), Eigen::Vector2d::Zero());
}

}  // namespace
}  // namespace wheelchair_sim
