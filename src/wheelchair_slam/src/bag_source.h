// A rosbag as a SLAM input for the slam tool (not the core): sensor_msgs/LaserScan on a topic,
// the laser's odometry pose from the bag's tf in the odometry frame (wheelchair_logs'
// BagScanReader, which needs ROS's tf2 and rosbag).
#pragma once

#include <wheelchair_logs/log_scan.h>

#include <memory>
#include <string>

namespace wheelchair_slam {

class BagOdometryReader {
 public:
  BagOdometryReader(const std::string& path, const std::string& scan_topic,
                    const std::string& odom_frame);
  ~BagOdometryReader();
  /// Next scan with its laser pose in odom_frame as the odometry.
  bool next(wheelchair_logs::LogScan& out);
  const std::string& problemsOfLastCall() const;
  size_t corruptLines() const;
  double progress() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace wheelchair_slam
