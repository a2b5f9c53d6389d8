// The simulated lasers (front and rear) against the analytic distance to a known wall.
#include <wheelchair_sim/laser_simulator.h>
#include <wheelchair_sim/simulated_chair.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wheelchair_sim {
namespace {

constexpr double kRes = 0.05;

TEST(Laser, BeamCountAndAnglesAreTheSicks) {
  SimParams params;
  LaserSimulator laser(params, wheelchair_core::Pose2D(), test::wallWorld(3.0));
  const wheelchair_core::LaserScan2D scan = laser.scan(wheelchair_core::Pose2D());
  ASSERT_EQ(scan.ranges.size(), 361u);
  EXPECT_NEAR(scan.angle_min, -M_PI / 2, 1e-12);
  EXPECT_NEAR(scan.angle_max, M_PI / 2, 1e-12);
  EXPECT_NEAR(scan.angle_increment, 0.5 * M_PI / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(scan.range_max, params.laser_range_max);
}

// Wall face at x = 3; chair at (0.4, -0.6), heading 0.3; laser mounted 0.28 m ahead of P.
TEST(Laser, RangesMatchTheAnalyticWallDistance) {
  const auto chair = test::chair();
  SimParams params;
  params.laser_range_noise = 0.01;
  const wheelchair_core::Pose2D mount{chair.laser_x, chair.laser_y, chair.laser_yaw};
  LaserSimulator laser(params, mount, test::wallWorld(3.0));
  const wheelchair_core::Pose2D base{0.4, -0.6, 0.3};
  const wheelchair_core::Pose2D sensor = laser.laserPose(base);
  EXPECT_NEAR(sensor.x, 0.4 + chair.laser_x * std::cos(0.3), 1e-12);
  const wheelchair_core::LaserScan2D scan = laser.scan(base);
  int checked = 0, no_return = 0;
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const double a = sensor.yaw + scan.angle_min + i * scan.angle_increment;
    const double expected = (3.0 - sensor.x) / std::cos(a);
    const double hit_y = sensor.y + expected * std::sin(a);
    if (std::cos(a) > 0.05 && std::abs(hit_y) < 4.8 && expected < params.laser_range_max) {
      // Noise (4 sigma) + MRPT's ray marching resolution (one cell along the ray).
      EXPECT_NEAR(scan.ranges[i], expected, 4 * params.laser_range_noise + kRes / std::cos(a))
          << "beam " << i;
      ++checked;
    } else if (std::cos(a) < 0.0) {
      EXPECT_TRUE(std::isinf(scan.ranges[i])) << "beam " << i << " leaves the map: no return";
      ++no_return;
    }
  }
  EXPECT_GT(checked, 250);
  EXPECT_GT(no_return, 10);
}

TEST(Laser, RangeNoiseHasTheConfiguredSpread) {
  SimParams exact, noisy;
  exact.laser_range_noise = 0.0;
  noisy.laser_range_noise = 0.03;
  auto world = test::wallWorld(4.0);
  LaserSimulator reference(exact, wheelchair_core::Pose2D(), world);
  LaserSimulator laser(noisy, wheelchair_core::Pose2D(), world);
  const wheelchair_core::Pose2D base{0.0, 0.0, 0.0};
  const wheelchair_core::LaserScan2D truth = reference.scan(base);
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  for (int k = 0; k < 20; ++k) {
    const wheelchair_core::LaserScan2D scan = laser.scan(base);
    for (size_t i = 0; i < scan.ranges.size(); ++i) {
      if (!std::isfinite(truth.ranges[i]) || !std::isfinite(scan.ranges[i])) continue;
      const double e = scan.ranges[i] - truth.ranges[i];
      sum += e;
      sum2 += e * e;
      ++n;
    }
  }
  ASSERT_GT(n, 3000);
  const double mean = sum / n, stddev = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0.0, 4 * noisy.laser_range_noise / std::sqrt(n));
  EXPECT_NEAR(stddev, noisy.laser_range_noise, 0.1 * noisy.laser_range_noise);
}

// The rear laser looks behind the chair from its mount 0.75 m behind the axle: with the chair
// facing away from the wall (yaw pi) it sees the wall, its centre beam at the analytic distance,
// while the front laser sees nothing within the world's far side.
TEST(Laser, TheRearLaserSeesTheWallBehindTheChair) {
  const auto chair = test::chair();
  SimParams params;
  params.laser_range_noise = 0.0;
  SimulatedChair sim(chair, params, test::wallWorld(3.0, -5.0, 10.0));
  ASSERT_TRUE(sim.hasRearLaser());
  ASSERT_TRUE(sim.teleport({1.0, 0.0, M_PI}));
  std::optional<wheelchair_core::LaserScan2D> rear, front;
  for (int i = 0; i < 200 && !rear; ++i) {
    SensorOutputs out = sim.advance(0.005);
    rear = out.rear_scan;
    front = out.scan;
  }
  ASSERT_TRUE(rear && front);
  ASSERT_EQ(rear->ranges.size(), 361u);
  EXPECT_DOUBLE_EQ(rear->range_max, params.rear_laser_range_max);
  // Centre beam: the laser at x = 1 - 0.75 cos(pi) = 1.75 looks along +x to the face at 3.
  const double centre = rear->ranges[180];
  EXPECT_NEAR(centre, 3.0 - (1.0 - chair.rear_laser_x), kRes) << "rear centre beam";
  // The front laser looks along -x: its centre beam hits the world's edge, far away.
  EXPECT_GT(front->ranges[180], 5.0);
  // Off: no rear scans at all.
  SimParams no_rear = params;
  no_rear.rear_laser_enabled = false;
  SimulatedChair without(chair, no_rear, test::wallWorld(3.0));
  EXPECT_FALSE(without.hasRearLaser());
}

TEST(Laser, SameSeedSameScan) {
  SimParams params;
  auto world = test::wallWorld(2.0);
  LaserSimulator a(params, wheelchair_core::Pose2D(), world),
      b(params, wheelchair_core::Pose2D(), world);
  EXPECT_EQ(a.scan(wheelchair_core::Pose2D()).ranges, b.scan(wheelchair_core::Pose2D()).ranges);
}

}  // namespace
}  // namespace wheelchair_sim
