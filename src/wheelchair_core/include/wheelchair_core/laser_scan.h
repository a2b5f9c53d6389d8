// The one laser-scan type of the project: sensor_msgs/LaserScan's fields without ROS, and the
// REP-117 rules that say what each beam means. Every package that reads a scan (mapping,
// localization, safety, simulator, log readers) uses this type and these rules.
#pragma once

#include <wheelchair_core/pose2d.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>
#include <vector>

namespace wheelchair_core {

struct LaserScan2D {
  double stamp = 0.0;            ///< [s]
  double angle_min = 0.0;        ///< angle of ranges[0] in the sensor frame [rad]
  double angle_max = 0.0;        ///< angle of the last range [rad]
  double angle_increment = 0.0;  ///< [rad], negative for clockwise scanners
  double range_min = 0.0;        ///< [m]
  double range_max = 0.0;        ///< [m]
  /// [m]; REP-117: NaN erroneous, -inf too close, +inf no return within range_max; finite
  /// values outside [range_min, range_max] are to be discarded.
  std::vector<float> ranges;

  /// Angle of beam `i` in the sensor frame [rad].
  double angle(size_t i) const { return angle_min + static_cast<double>(i) * angle_increment; }
};

/// What one beam says (REP-117).
enum class Beam {
  kReturn,       ///< an echo at a range within [range_min, range_max]
  kNoReturn,     ///< +inf: nothing within range_max along the beam
  kTooClose,     ///< -inf: something closer than range_min
  kInvalid,      ///< NaN: an erroneous reading
  kOutOfLimits,  ///< finite but outside [range_min, range_max]: discarded
};

/// The meaning of `range` in `scan`.
Beam classifyBeam(float range, const LaserScan2D& scan);

/// Empty if the scan's geometry is usable, else the reason: no beams, non-finite angles or stamp,
/// a zero increment, bad range limits, a beam count that disagrees with angle_min / angle_max /
/// angle_increment or with `expected_beams` (0: any).
std::string scanGeometryProblem(const LaserScan2D& scan, size_t expected_beams = 0);

/// Number of beams that are returns.
size_t countReturns(const LaserScan2D& scan);

/// The returns of `scan` as points in the frame in which `sensor_pose` is given.
std::vector<Eigen::Vector2d> scanEndpoints(const LaserScan2D& scan, const Pose2D& sensor_pose);

/// The same scan seen by the sensor mounted upside down (its angles turn the other way).
void mirrorScanAngles(LaserScan2D& scan);

}  // namespace wheelchair_core
