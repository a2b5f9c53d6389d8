// Test helpers: a synthetic room with known walls (the ground truth) and laser scans simulated
// in it by MRPT from known poses.
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/random/RandomGenerators.h>
#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_mapping/mrpt_conversions.h>
#include <wheelchair_mapping/mrpt_scan.h>

#include <cmath>
#include <vector>

namespace wheelchair_mapping::test {

/// A 10 m x 8 m room (walls 0.1 m thick) with a 1.0 x 0.6 m box and an L-shaped partition.
inline wheelchair_core::OccupancyMap syntheticRoom() {
  wheelchair_core::OccupancyMap map;
  map.resolution = 0.05;
  map.origin_x = -1.0;
  map.origin_y = -1.0;
  map.width = 240;
  map.height = 200;
  map.data.assign(static_cast<size_t>(map.width) * map.height, wheelchair_core::kFree);
  auto box = [&map](double x0, double y0, double x1, double y1) {
    for (int iy = 0; iy < map.height; ++iy) {
      for (int ix = 0; ix < map.width; ++ix) {
        double x, y;
        map.cellToWorld(ix, iy, x, y);
        if (x > x0 && x < x1 && y > y0 && y < y1) map.at(ix, iy) = wheelchair_core::kOccupied;
      }
    }
  };
  box(0.0, 0.0, 10.0, 0.1);  // outer walls
  box(0.0, 7.9, 10.0, 8.0);
  box(0.0, 0.0, 0.1, 8.0);
  box(9.9, 0.0, 10.0, 8.0);
  box(4.0, 3.5, 5.0, 4.1);  // box
  box(7.0, 5.0, 7.1, 7.9);  // partition from the top wall
  box(7.0, 5.0, 8.5, 5.1);
  return map;
}

/// 30 sensor poses along a loop through the room (the paper's protocol: 30 scans).
inline std::vector<wheelchair_core::Pose2D> loopTrajectory() {
  std::vector<wheelchair_core::Pose2D> poses;
  for (int k = 0; k < 30; ++k) {
    const double t = 2 * M_PI * k / 30;
    poses.push_back({5.0 + 3.2 * std::cos(t), 4.0 + 2.4 * std::sin(t), t + M_PI / 2});
  }
  return poses;
}

/// 361 beams over 180 deg (SICK LMS), range_max 8 m, simulated by MRPT in `truth` from `pose`.
/// MRPT's simulator gives up (no echo) at about 0.8 maxRange, so it is asked for 1.5 x range_max
/// and returns beyond range_max are turned into +inf (no return within range), as a real
/// scanner reports them.
inline wheelchair_core::LaserScan2D simulateScan(const mrpt::maps::COccupancyGridMap2D& truth,
                                                 const wheelchair_core::Pose2D& pose, double stamp,
                                                 double noise_std = 0.0) {
  constexpr double kRangeMax = 8.0;
  mrpt::obs::CObservation2DRangeScan obs;
  obs.aperture = static_cast<float>(M_PI);
  obs.maxRange = static_cast<float>(1.5 * kRangeMax);
  obs.rightToLeft = true;
  truth.laserScanSimulator(obs, mrpt::poses::CPose2D(pose.x, pose.y, pose.yaw), 0.5f, 361,
                           static_cast<float>(noise_std));
  wheelchair_core::LaserScan2D scan = laserScanFromMrpt(obs, stamp);
  scan.range_max = kRangeMax;
  for (float& r : scan.ranges) {
    if (r > kRangeMax) r = INFINITY;
  }
  return scan;
}

}  // namespace wheelchair_mapping::test
