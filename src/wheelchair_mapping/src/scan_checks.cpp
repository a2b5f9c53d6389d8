#include <wheelchair_mapping/scan_checks.h>

#include <cmath>
#include <sstream>

namespace wheelchair_mapping {

std::string scanProblem(const LaserScan2D& scan, size_t expected_beams) {
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

BeamUse useOfBeam(float range, const LaserScan2D& scan, const InverseSensorModel& model) {
  BeamUse use;
  if (std::isnan(range) || range == -INFINITY) return use;
  if (range == INFINITY) {
    if (!model.no_return_is_free) return use;
    const double free_range = model.no_return_range > 0 ? model.no_return_range : scan.range_max;
    use.kind = BeamUse::kPassThrough;
    use.length = std::min(free_range, model.max_insertion_range);
    return use;
  }
  if (range < scan.range_min || range > scan.range_max) return use;
  if (range > model.max_insertion_range) {
    use.kind = BeamUse::kPassThrough;
    use.length = model.max_insertion_range;
    return use;
  }
  use.kind = BeamUse::kHit;
  use.length = range;
  return use;
}

}  // namespace wheelchair_mapping
