#include <wheelchair_core/laser_scan.h>

#include <cmath>
#include <sstream>

namespace wheelchair_core {

Beam classifyBeam(float range, const LaserScan2D& scan) {
  if (std::isnan(range)) return Beam::kInvalid;
  if (range == -INFINITY) return Beam::kTooClose;
  if (range == INFINITY) return Beam::kNoReturn;
  if (range < scan.range_min || range > scan.range_max) return Beam::kOutOfLimits;
  return Beam::kReturn;
}

std::string scanGeometryProblem(const LaserScan2D& scan, size_t expected_beams) {
  std::ostringstream msg;
  if (scan.ranges.empty()) return "scan has no beams";
  if (!std::isfinite(scan.angle_min) || !std::isfinite(scan.angle_max) ||
      !std::isfinite(scan.angle_increment) || scan.angle_increment == 0.0) {
    return "scan angles are not finite or the increment is zero";
  }
  if (!std::isfinite(scan.stamp)) return "scan stamp is not finite";
  if (!(scan.range_min >= 0.0 && scan.range_max > scan.range_min) ||
      !std::isfinite(scan.range_max)) {
    return "scan range limits are invalid";
  }
  const double span = (scan.angle_max - scan.angle_min) / scan.angle_increment;
  const long geometric = std::lround(span) + 1;
  if (std::abs(span - std::round(span)) > 1e-3 ||
      geometric != static_cast<long>(scan.ranges.size())) {
    msg << "wrong beam count: " << scan.ranges.size() << " ranges but the angles give "
        << geometric;
    return msg.str();
  }
  if (expected_beams > 0 && scan.ranges.size() != expected_beams) {
    msg << "wrong beam count: " << scan.ranges.size() << " ranges, expected " << expected_beams;
    return msg.str();
  }
  return "";
}

size_t countReturns(const LaserScan2D& scan) {
  size_t n = 0;
  for (float r : scan.ranges) n += classifyBeam(r, scan) == Beam::kReturn;
  return n;
}

std::vector<Eigen::Vector2d> scanEndpoints(const LaserScan2D& scan, const Pose2D& sensor_pose) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(scan.ranges.size());
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const float r = scan.ranges[i];
    if (classifyBeam(r, scan) != Beam::kReturn) continue;
    const double a = sensor_pose.yaw + scan.angle(i);
    points.emplace_back(sensor_pose.x + r * std::cos(a), sensor_pose.y + r * std::sin(a));
  }
  return points;
}

void mirrorScanAngles(LaserScan2D& scan) {
  scan.angle_min = -scan.angle_min;
  scan.angle_max = -scan.angle_max;
  scan.angle_increment = -scan.angle_increment;
}

}  // namespace wheelchair_core
