#include <wheelchair_kld/laser_scan.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace wheelchair_kld {

std::string validateScan(const LaserScan& scan, int expected_beams, double min_valid_fraction) {
  std::ostringstream why;
  if (scan.ranges.empty()) return "scan has no beams";
  if (expected_beams > 0 && static_cast<int>(scan.ranges.size()) != expected_beams) {
    why << "scan has " << scan.ranges.size() << " beams, expected " << expected_beams;
    return why.str();
  }
  if (!std::isfinite(scan.angle_min) || !std::isfinite(scan.angle_increment) ||
      !std::isfinite(scan.range_max) || scan.range_max <= 0 || !std::isfinite(scan.sensor_pose.x) ||
      !std::isfinite(scan.sensor_pose.y) || !std::isfinite(scan.sensor_pose.phi))
    return "scan geometry is not finite";
  size_t valid = 0;
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const float r = scan.ranges[i];
    if (std::isnan(r) || r == -std::numeric_limits<float>::infinity()) {
      why << "scan range " << i << " is " << r;
      return why.str();
    }
    if (std::isfinite(r) && r >= scan.range_min && r < scan.range_max) ++valid;
  }
  if (valid < min_valid_fraction * scan.ranges.size()) {
    why << "only " << valid << " of " << scan.ranges.size() << " beams have an echo";
    return why.str();
  }
  return "";
}

LaserScan fromMrptScan(const mrpt::obs::CObservation2DRangeScan& obs) {
  LaserScan s;
  const size_t n = obs.getScanSize();
  s.ranges.resize(n);
  for (size_t i = 0; i < n; ++i)
    s.ranges[i] =
        obs.getScanRangeValidity(i) ? obs.getScanRange(i) : std::numeric_limits<float>::infinity();
  s.angle_min = obs.rightToLeft ? -obs.aperture / 2 : obs.aperture / 2;
  s.angle_increment = (obs.rightToLeft ? 1.0 : -1.0) * obs.aperture / (n > 1 ? n - 1 : 1);
  s.range_max = obs.maxRange;
  const auto p = obs.sensorPose.asTPose();
  s.sensor_pose = mrpt::math::TPose2D(p.x, p.y, p.yaw);
  return s;
}

}  // namespace wheelchair_kld
