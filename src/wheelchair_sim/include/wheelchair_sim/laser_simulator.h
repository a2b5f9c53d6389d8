// A SICK-like planar laser scanner ray-cast on the ground-truth grid with MRPT.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_sim/obstacle_discs.h>
#include <wheelchair_sim/sim_params.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <memory>
#include <random>
#include <vector>

namespace wheelchair_sim {

class LaserSimulator {
 public:
  /// `mount`: the laser in base_link (ChairParams laser_x, laser_y, laser_yaw). Throws
  /// std::invalid_argument for invalid params or no world.
  LaserSimulator(const SimParams& params, const wheelchair_core::Pose2D& mount,
                 std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world);

  /// The scan seen with base_link at `base_pose` in the world, with `discs` (obstacles not in
  /// the map) in front of the walls: beam i points at angle(i) in the laser frame
  /// (counter-clockwise, x forward); no return -> +Inf (REP-117). Stamp 0: the caller's.
  wheelchair_core::LaserScan2D scan(const wheelchair_core::Pose2D& base_pose,
                                    const std::vector<Disc>& discs = {});

  /// World pose of the laser for a base_link pose (its yaw not wrapped).
  wheelchair_core::Pose2D laserPose(const wheelchair_core::Pose2D& base_pose) const;

 private:
  SimParams params_;
  wheelchair_core::Pose2D mount_;
  std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world_;
  std::mt19937_64 rng_;
};

}  // namespace wheelchair_sim
