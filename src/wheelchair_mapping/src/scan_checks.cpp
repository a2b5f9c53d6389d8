#include <wheelchair_mapping/scan_checks.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wheelchair_mapping {

using wheelchair_core::Beam;

BeamUse useOfBeam(float range, const wheelchair_core::LaserScan2D& scan,
                  const InverseSensorModel& model) {
  BeamUse use;
  switch (wheelchair_core::classifyBeam(range, scan)) {
    case Beam::kNoReturn: {
      if (!model.no_return_is_free) return use;
      const double free_range = model.no_return_range > 0 ? model.no_return_range : scan.range_max;
      use.kind = BeamUse::kPassThrough;
      use.length = std::min(free_range, model.max_insertion_range);
      return use;
    }
    case Beam::kReturn:
      if (range > model.max_insertion_range) {
        use.kind = BeamUse::kPassThrough;
        use.length = model.max_insertion_range;
      } else {
        use.kind = BeamUse::kHit;
        use.length = range;
      }
      return use;
    case Beam::kTooClose:
    case Beam::kInvalid:
    case Beam::kOutOfLimits:
      break;
  }
  return use;
}

std::string scanInsertProblem(const wheelchair_core::LaserScan2D& scan,
                              const wheelchair_core::Pose2D& pose, size_t expected_beams,
                              double last_stamp) {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.yaw))
    return "sensor pose is not finite";
  const std::string geometry = wheelchair_core::scanGeometryProblem(scan, expected_beams);
  if (!geometry.empty()) return geometry;
  if (scan.stamp < last_stamp) {
    std::ostringstream msg;
    msg.precision(15);
    msg << "time went backwards: scan at " << scan.stamp << " s after one at " << last_stamp
        << " s";
    return msg.str();
  }
  return "";
}

}  // namespace wheelchair_mapping
