// Laser scans with their poses from a rosbag (library wheelchair_logs_bag): sensor_msgs/
// LaserScan on a topic, and the laser pose in a fixed frame from the bag's /tf and /tf_static
// (and, for a localizer replay, the robot's odometry: the base frame's pose in the fixed frame,
// from tf or from nav_msgs/Odometry messages).
// The header names no ROS type, so an offline tool includes it without ROS include paths.
#pragma once

#include <wheelchair_logs/log_scan.h>

#include <cstddef>
#include <memory>
#include <string>

namespace wheelchair_logs {

class BagScanReader {
 public:
  /// Reads every tf message of the bag first (and every nav_msgs/Odometry on `odom_topic`, as
  /// the transform header.frame_id -> child_frame_id). With a `base_frame`, LogScan::odom_pose
  /// is base_frame's pose in fixed_frame at the scan's stamp (else the laser pose). Throws
  /// std::runtime_error naming the file if it cannot be opened.
  BagScanReader(const std::string& path, const std::string& scan_topic,
                const std::string& fixed_frame, const std::string& base_frame = "",
                const std::string& odom_topic = "");
  ~BagScanReader();
  BagScanReader(const BagScanReader&) = delete;
  BagScanReader& operator=(const BagScanReader&) = delete;

  /// Next scan whose laser pose is known; scans without tf at their stamp are reported by
  /// problemsOfLastCall() ("<file>:<message index>: ...") and skipped.
  bool next(LogScan& out);
  const std::string& problemsOfLastCall() const { return problems_; }
  /// Scans skipped so far for want of tf.
  size_t problemCount() const { return skipped_; }
  double progress() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_, fixed_frame_, base_frame_;
  std::string problems_;
  size_t skipped_ = 0;
};

}  // namespace wheelchair_logs
