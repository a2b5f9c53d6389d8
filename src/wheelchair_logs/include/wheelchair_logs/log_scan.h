// One laser scan of a recorded drive, as every log reader of the project returns it.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>

#include <cstddef>

namespace wheelchair_logs {

struct LogScan {
  wheelchair_core::LaserScan2D scan;
  wheelchair_core::Pose2D laser_pose;  ///< pose of the laser in the log's world frame
  /// The second pose of the line: FLASER's odom_x odom_y odom_theta, ROBOTLASER1's robot pose
  /// (in a derived_*_gt_rawodom log the raw odometry beside the corrected laser_pose; with
  /// OdometrySource::kGfsIncrements the raw odometry rebuilt from ODOM lines); a bag reader:
  /// the base frame's pose when asked for, else the laser pose.
  wheelchair_core::Pose2D odom_pose;
  size_t line = 0;  ///< 1-based line number in the log (message index in a bag)
};

}  // namespace wheelchair_logs
