// Trajectories on disk: CSV (stamp,x,y,yaw) and the CARMEN corrected-log format (FLASER lines
// whose pose is the estimate and whose odom fields are the raw odometry, as in the
// derived_*_gt_rawodom.clf files), which build_map and replay read.
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_logs/timed_pose.h>

#include <string>
#include <vector>

namespace wheelchair_slam {

using wheelchair_logs::TimedPose;

/// Throws std::runtime_error naming the file if it cannot be written.
void writeTrajectoryCsv(const std::string& path, const std::vector<TimedPose>& poses);
/// Throws std::runtime_error naming the file and line for a bad file.
std::vector<TimedPose> readTrajectoryCsv(const std::string& path);

/// One FLASER line per scan: the scan's ranges (+inf written as `no_echo`), the estimated pose,
/// the odometry, the stamp. The scans must have 180/181/360/361 beams over 180 deg (FLASER).
void writeCarmenLog(const std::string& path, const std::vector<wheelchair_core::LaserScan2D>& scans,
                    const std::vector<wheelchair_core::Pose2D>& poses,
                    const std::vector<wheelchair_core::Pose2D>& odometry, double no_echo = 81.91);

}  // namespace wheelchair_slam
