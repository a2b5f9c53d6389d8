// Synthetic worlds and drives for tests and benchmarks: ground-truth poses along a route, noisy
// wheel odometry and 361-beam scans simulated with COccupancyGridMap2D::laserScanSimulator.
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <wheelchair_kld/laser_scan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_kld {

/// The MRPT grid of a map_server YAML map (e.g. the project's test/worlds/office.yaml).
mrpt::maps::COccupancyGridMap2D loadWorldGrid(const std::string& yaml_path);

/// A route through the doors of a project test world ("flat", "office", "symmetric"), as
/// waypoints (the heading follows the path); throws std::invalid_argument for other names.
std::vector<mrpt::math::TPose2D> worldRoute(const std::string& name);

struct DriveParams {
  double step = 0.1;               ///< [m] travel between scans (rotation steps: 0.1 rad)
  double odom_trans_noise = 0.02;  ///< relative std of odometry translation
  double odom_rot_noise = 0.02;    ///< [rad/rad] relative std of odometry rotation
  double range_noise = 0.01;       ///< [m] std of simulated ranges
  int beams = 361;                 ///< over 180 degrees
  double max_range = 30.0;
  mrpt::math::TPose2D sensor_pose{0.3, 0.0, 0.0};  ///< laser in base_link
  uint32_t seed = 1;
};

struct DriveSample {
  mrpt::math::TPose2D truth;  ///< base_link in the map frame
  mrpt::math::TPose2D odom;   ///< base_link in the odom frame (drifting)
  LaserScan scan;
};

/// Drives along `route` (turn in place, then straight) and samples every `step`.
std::vector<DriveSample> simulateDrive(const mrpt::maps::COccupancyGridMap2D& grid,
                                       const std::vector<mrpt::math::TPose2D>& route,
                                       const DriveParams& params);

/// The scan seen from `truth` (base_link in the map frame).
LaserScan simulateScan(const mrpt::maps::COccupancyGridMap2D& grid,
                       const mrpt::math::TPose2D& truth, const DriveParams& params, uint32_t seed);

}  // namespace wheelchair_kld
