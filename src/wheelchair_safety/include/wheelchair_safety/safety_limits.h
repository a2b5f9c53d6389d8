// The supervisor's limits: when a condition becomes a stop. Defaults here only; validate() says
// what is wrong; readSafetyLimits() names every key (the nodelet's private parameters, or a YAML
// file read by an offline tool).
#pragma once

#include <wheelchair_core/config.h>

#include <string>

namespace wheelchair_safety {

struct SafetyLimits {
  double scan_timeout = 0.3;          ///< [s] laser silent this long -> stop
  double pose_timeout = 0.3;          ///< [s] map->base_link (tf) older than this -> stop
  double localization_timeout = 1.0;  ///< [s] no localization status this long -> stop
  double max_position_std = 0.20;     ///< [m] largest std-dev of the x-y covariance
  double max_heading_std = 0.20;      ///< [rad]
  double stop_distance = 1.2;         ///< [m] watched along the path ahead of the chair
  double corridor_half_width = 0.41;  ///< [m] chair half-width + 10 cm either side of the path
  double map_tolerance = 0.15;        ///< [m] a return this close to a mapped obstacle is the map
  int min_obstacle_returns = 3;       ///< returns needed to call an obstacle (noise rejection)
  /// [s] a driver fault must last this long: the driver brakes at once by itself, and a motor
  /// controller that re-arms within one command period (a late command) is not worth a
  /// latched stop; a fault that persists (hardware, lost bus) is.
  double driver_fault_grace = 0.25;
  // Behind the chair (rear_guard.h), while the path backs up.
  double rear_scan_timeout = 0.3;  ///< [s] rear laser silent this long -> no reverse motion
  /// [m] watched behind the body's rear: reverse speed is at most 0.3 m/s, which stops within
  /// 0.3 * 0.2 s + 0.3^2 / (2 * 0.5 m/s^2) = 0.15 m; the rest is margin.
  double rear_stop_distance = 0.5;
  double rear_overhang = 0.80;  ///< [m] the body's reach behind the axle (chair.yaml footprint)
  /// The pose is a localizer's: its status (/localization/status) and covariance are watched.
  /// false in mapping mode: SLAM's map -> odom is the pose (its age, the laser, the field ahead
  /// and the driver are still watched), there is no localizer to wait for.
  bool require_localizer = true;

  /// "" if usable, else every problem.
  std::string validate() const;
};

/// The keys of SafetyLimits, named as the fields.
void readSafetyLimits(wheelchair_core::ConfigReader& reader, SafetyLimits& limits);

}  // namespace wheelchair_safety
