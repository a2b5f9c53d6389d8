// The protective field: how far along the path the supervisor watches, scaled to the chair's
// speed, and the speed at which the chair can still stop within what the laser sees.
//
//   stop zone (along the path, from the chair's front): d_stop(v) = the distance of the
//     controlled stop from v + margin, worst case: still accelerating at a_drive for the
//     reaction time t_react, then the jerk-limited brake (jerk j_brake) from +a_drive to
//     -a_brake, then -a_brake to rest; ~ v t_react + v^2 / (2 a_brake) + margin plus the ramps
//   slow-down zone: beyond the stop zone, up to slowdown_length; a return there at s limits
//     the speed to maxStoppableSpeed(s) (Nav2 collision monitor's "approach" model, in
//     distance along the path instead of time to collision);
//   view limit: the same speed limit for the length of path the laser sees (range, field of
//     view, occlusion), unless it sees the path to its end.
// ROS-free; the supervisor (safety_supervisor.h) uses it.
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/pose2d.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace wheelchair_safety {

/// The chair's stopping behaviour and the field's shape. The brake values are the controlled
/// stop's (wheelchair_controller: the path's comfort limits max_accel 0.5 m/s^2 and max_jerk
/// 1.0 m/s^3, driving with limit_margin 0.7 of them: 0.35 m/s^2); the front is the footprint's
/// (chair.yaml: x = 0.30 m).
struct ProtectiveField {
  double reaction_time =
      0.3;                    ///< [s] scan period 0.1 + check 0.05 + control 0.02 + bus, rounded up
  double brake_decel = 0.5;   ///< [m/s^2] of the controlled stop
  double brake_jerk = 1.0;    ///< [m/s^3] of the controlled stop
  double drive_accel = 0.35;  ///< [m/s^2] largest acceleration while driving a path
  double margin = 0.2;        ///< [m] left between the chair's front and what it stops for
  double front_offset = 0.30;    ///< [m] the footprint's front ahead of the axle centre
  double slowdown_length = 5.0;  ///< [m] watched beyond the stop zone, from the front
  double view_tolerance = 0.10;  ///< [m] a path point this far behind a return is still seen

  std::string validate() const;
  /// The stop zone's length ahead of the chair's front [m] at forward speed v [m/s].
  double stopDistance(double v) const;
  /// The largest speed whose stop zone fits within `distance` from the front (0 if none).
  double maxStoppableSpeed(double distance) const;
};

/// Keys: field/reaction_time, field/brake_decel, field/brake_jerk, field/drive_accel,
/// field/margin, field/front_offset, field/slowdown_length, field/view_tolerance.
void readProtectiveField(wheelchair_core::ConfigReader& reader, ProtectiveField& field);

/// The path ahead of a chair at `here`: from `here` to the nearest place on the path, then on
/// along the path for at most `length` [m].
std::vector<Eigen::Vector2d> pathAhead(const std::vector<Eigen::Vector2d>& path,
                                       const Eigen::Vector2d& here, double length);
/// Distance along `ahead` [m] of the place nearest to `point`, if `point` lies within
/// `half_width` of it; +inf if it is not in that corridor.
double distanceAlongCorridor(const std::vector<Eigen::Vector2d>& ahead,
                             const Eigen::Vector2d& point, double half_width);
/// How far along `ahead` [m] the laser (its scan and its pose, in the frame of `ahead`) sees
/// the path's centre line, checked where it is `from` [m] or more from ahead[0] (the axle: what
/// lies under the chair is not the laser's) and 0.15 m ahead of the laser: the first point (0.05 m
/// steps) outside the field of view, beyond range_max, behind a return (more than `tolerance`) or
/// along an unusable beam ends it. Returns the length of `ahead` if it sees it all. `why`
/// (optional): what ended it, for the log (null if nothing).
double visibleLength(const std::vector<Eigen::Vector2d>& ahead,
                     const wheelchair_core::LaserScan2D& scan,
                     const wheelchair_core::Pose2D& laser_pose, double from, double tolerance,
                     const char** why = nullptr);

}  // namespace wheelchair_safety
