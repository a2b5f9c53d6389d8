// Test and bench harness (library wheelchair_kld_test_support, never installed): synthetic
// drives through the project's test worlds -- ground-truth poses along a route, noisy wheel
// odometry and 361-beam scans simulated with COccupancyGridMap2D::laserScanSimulator.
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>

#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_kld::test {

/// The MRPT grid of a map_server YAML map (e.g. the project's test/worlds/office.yaml).
mrpt::maps::COccupancyGridMap2D loadWorldGrid(const std::string& yaml_path);

/// A route through the doors of a project test world ("flat", "office", "symmetric"), as
/// waypoints (the heading follows the path); throws std::invalid_argument for other names.
std::vector<wheelchair_core::Pose2D> worldRoute(const std::string& name);

struct DriveParams {
  double step = 0.1;               ///< [m] travel between scans (rotation steps: 0.1 rad)
  double odom_trans_noise = 0.02;  ///< relative std of odometry translation
  double odom_rot_noise = 0.02;    ///< [rad/rad] relative std of odometry rotation
  double range_noise = 0.01;       ///< [m] std of simulated ranges
  int beams = 361;                 ///< over 180 degrees
  double range_min = 0.05;         ///< [m] of the simulated scanner
  double max_range = 30.0;
  wheelchair_core::Pose2D sensor_pose{0.3, 0.0, 0.0};  ///< laser in base_link
  uint32_t seed = 1;
};

struct DriveSample {
  wheelchair_core::Pose2D truth;        ///< base_link in the map frame
  wheelchair_core::Pose2D odom;         ///< base_link in the odom frame (drifting)
  wheelchair_core::LaserScan2D scan;    ///< stamped with the sample's index
  wheelchair_core::Pose2D sensor_pose;  ///< laser in base_link
};

/// Drives along `route` (turn in place, then straight) and samples every `step`.
std::vector<DriveSample> simulateDrive(const mrpt::maps::COccupancyGridMap2D& grid,
                                       const std::vector<wheelchair_core::Pose2D>& route,
                                       const DriveParams& params);

/// The scan seen from `truth` (base_link in the map frame) by the laser at params.sensor_pose.
wheelchair_core::LaserScan2D simulateScan(const mrpt::maps::COccupancyGridMap2D& grid,
                                          const wheelchair_core::Pose2D& truth,
                                          const DriveParams& params, uint32_t seed);

}  // namespace wheelchair_kld::test
