#include <wheelchair_safety/safety_limits.h>

namespace wheelchair_safety {

std::string SafetyLimits::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.positive("scan_timeout", scan_timeout)
      .positive("pose_timeout", pose_timeout)
      .positive("localization_timeout", localization_timeout)
      .positive("max_position_std", max_position_std)
      .positive("max_heading_std", max_heading_std)
      .positive("stop_distance", stop_distance)
      .positive("corridor_half_width", corridor_half_width)
      .nonNegative("map_tolerance", map_tolerance)
      .nonNegative("driver_fault_grace", driver_fault_grace)
      .positive("rear_scan_timeout", rear_scan_timeout)
      .positive("rear_stop_distance", rear_stop_distance)
      .nonNegative("rear_overhang", rear_overhang)
      .check(min_obstacle_returns >= 1, "min_obstacle_returns must be at least 1 (got " +
                                            std::to_string(min_obstacle_returns) + ")");
  return checks.result();
}

void readSafetyLimits(wheelchair_core::ConfigReader& reader, SafetyLimits& limits) {
  reader.read("scan_timeout", limits.scan_timeout);
  reader.read("pose_timeout", limits.pose_timeout);
  reader.read("localization_timeout", limits.localization_timeout);
  reader.read("max_position_std", limits.max_position_std);
  reader.read("max_heading_std", limits.max_heading_std);
  reader.read("stop_distance", limits.stop_distance);
  reader.read("corridor_half_width", limits.corridor_half_width);
  reader.read("map_tolerance", limits.map_tolerance);
  reader.read("min_obstacle_returns", limits.min_obstacle_returns);
  reader.read("driver_fault_grace", limits.driver_fault_grace);
  reader.read("rear_scan_timeout", limits.rear_scan_timeout);
  reader.read("rear_stop_distance", limits.rear_stop_distance);
  reader.read("rear_overhang", limits.rear_overhang);
  reader.read("require_localizer", limits.require_localizer);
}

}  // namespace wheelchair_safety
