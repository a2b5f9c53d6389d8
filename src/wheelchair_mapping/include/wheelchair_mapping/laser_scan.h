// A ROS-free laser scan with sensor_msgs/LaserScan's fields and conventions (REP-117), and the
// sensor pose it was taken from.
#pragma once

#include <vector>

namespace wheelchair_mapping {

struct LaserScan2D {
  double stamp = 0.0;            ///< [s]
  double angle_min = 0.0;        ///< angle of ranges[0] in the sensor frame [rad]
  double angle_max = 0.0;        ///< angle of the last range [rad]
  double angle_increment = 0.0;  ///< [rad], negative for clockwise scanners
  double range_min = 0.0;        ///< [m]
  double range_max = 0.0;        ///< [m]
  /// [m]; NaN: erroneous, -inf: too close, +inf: no return within range_max; finite values
  /// outside [range_min, range_max] are discarded.
  std::vector<float> ranges;
};

struct Pose2D {
  double x = 0.0;
  double y = 0.0;
  double yaw = 0.0;
};

}  // namespace wheelchair_mapping
