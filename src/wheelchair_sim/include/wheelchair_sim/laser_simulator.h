// A SICK-like planar laser scanner ray-cast on the ground-truth grid with MRPT.
#pragma once

#include <wheelchair_sim/obstacle_discs.h>
#include <wheelchair_sim/sim_params.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>

#include <memory>
#include <random>
#include <vector>

namespace wheelchair_sim {

/// One scan in sensor_msgs/LaserScan terms: beam i points at angle_min + i angle_increment
/// in the laser frame (counter-clockwise, x forward); no return -> +Inf (REP-117).
struct Scan {
  double angle_min = 0.0;
  double angle_increment = 0.0;
  double range_min = 0.0;
  double range_max = 0.0;
  std::vector<float> ranges;
  double angleMax() const { return angle_min + angle_increment * (ranges.size() - 1); }
};

class LaserSimulator {
 public:
  /// `mount`: the laser in base_link (x, y, yaw) — ChairParams laser_x, laser_y, laser_yaw.
  LaserSimulator(const SimParams& params, const Eigen::Vector3d& mount,
                 std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world);

  /// Scan seen from base_link pose (x, y, theta) in the world, with `discs` (obstacles not
  /// in the map) in front of the walls.
  Scan scan(const Eigen::Vector3d& base_pose, const std::vector<Disc>& discs = {});

  /// World pose of the laser for a base_link pose.
  Eigen::Vector3d laserPose(const Eigen::Vector3d& base_pose) const;

 private:
  SimParams params_;
  Eigen::Vector3d mount_;
  std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world_;
  std::mt19937_64 rng_;
};

}  // namespace wheelchair_sim
