// The safety supervisor: watches localization, the laser, tf, the path ahead and the base
// driver, and demands a stop (controlled deceleration, then the brake) with a reason the
// rider and the carers can read. A stop latches: the chair moves again only on a new command
// from the rider. ROS-free; time is injected (seconds, any epoch).
#pragma once

#include <wheelchair_core/laser_scan.h>
#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_safety/protective_field.h>
#include <wheelchair_safety/rear_guard.h>
#include <wheelchair_safety/safety_limits.h>

#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

namespace wheelchair_safety {

enum class StopReason {
  kNone,
  kNoData,
  kLocalizationLost,
  kCovarianceTooLarge,
  kLaserSilent,
  kPoseStale,
  kUnexpectedObstacle,
  kDriverFault,
  kUserStop,
  kRearSensorSilent,  ///< the path backs up and the rear laser is silent (rear_guard.h)
  kObstacleBehind,    ///< something unmapped behind the chair on the path it backs along
};

/// Words for the rider: short, no frames or coordinates (e.g. "the laser scanner is silent").
const char* describe(StopReason reason);

struct SafetyVerdict {
  bool stop = false;
  StopReason reason = StopReason::kNone;
  std::string detail;  ///< for the log, e.g. "no laser scan for 0.52 s"
  double value = NAN;  ///< the measured quantity behind a stop (an age [s], a std-dev, a count)
  double limit = NAN;  ///< the limit it broke
};

/// The speed the chair may drive at now so that it can always stop within what it sees.
struct SpeedLimit {
  double speed = INFINITY;  ///< [m/s]; +inf: no limit from the field
  std::string detail;       ///< for the log, e.g. "laser sees 1.40 m of the path"
};

class SafetySupervisor {
 public:
  explicit SafetySupervisor(SafetyLimits limits = SafetyLimits(),
                            ProtectiveField field = ProtectiveField());

  void onMap(const wheelchair_core::OccupancyMap& map);
  /// The path being driven, in the map frame (empty: nothing ahead to watch).
  void onPath(const std::vector<wheelchair_core::Pose2D>& path);
  /// Localizer status: `localized` and the pose covariance (x, y, theta) in the map frame.
  void onLocalization(double stamp, bool localized, const Eigen::Matrix3d& covariance,
                      const std::string& why_not);
  /// The chair's pose (tf map -> base_link) and when it was valid.
  void onPose(double stamp, const wheelchair_core::Pose2D& pose);
  /// A laser scan's returns, already in the map frame; non-finite points are ignored. A return
  /// not in the map, in the corridor along the path, stops the chair within the stop zone
  /// (stop_distance from the axle, or longer at speed: protective_field.h) and limits the speed
  /// within the slow-down zone beyond it.
  void onScan(double stamp, const std::vector<Eigen::Vector2d>& returns_in_map);
  /// The same scan as the laser measured it and the laser's pose in the map frame: how much of
  /// the path ahead it sees (range, field of view, occlusion) limits the speed.
  void onLaserView(const wheelchair_core::LaserScan2D& scan,
                   const wheelchair_core::Pose2D& laser_in_map);
  /// The chair's forward speed [m/s] (odometry); it scales the protective field. Non-finite
  /// values are ignored.
  void onSpeed(double stamp, double forward_speed);
  /// The rear laser's returns in the map frame (rear_guard.h: they guard reverse motion).
  void onRearScan(double stamp, const std::vector<Eigen::Vector2d>& returns_in_map);
  /// The base driver's status at `stamp`; a fault counts once it has lasted driver_fault_grace.
  void onDriverStatus(double stamp, bool fault, const std::string& detail);
  void onUserStop(double stamp);
  /// A new command from the rider (a new goal): clears a latched stop. If a condition still
  /// holds, the next check() stops again.
  void onUserCommand(double stamp);

  /// The verdict at time `now`; once a stop is returned it latches until onUserCommand()
  /// (except kNoData: waiting for the first sensor data clears by itself).
  SafetyVerdict check(double now);

  const SafetyVerdict& latched() const { return latched_; }
  /// The speed limit from the field (slow-down zone, view); 0 while a stop holds.
  SpeedLimit speedLimit() const;
  /// The stop zone's extent along the path from the axle centre [m] at the last speed.
  double stopExtent() const;

 private:
  SafetyVerdict evaluate(double now) const;
  /// The localizer's status and covariance (when limits.require_localizer).
  SafetyVerdict evaluateLocalization(double now) const;
  bool knownObstacleNear(const Eigen::Vector2d& point) const;

  SafetyLimits limits_;
  ProtectiveField field_;
  double speed_ = 0.0;
  SpeedLimit obstacle_limit_, view_limit_;
  double nearest_unexpected_ = INFINITY;  ///< along the path from the axle [m]
  RearGuard rear_;
  wheelchair_core::OccupancyMap map_;
  std::vector<Eigen::Vector2d> path_;
  double scan_stamp_ = -1.0, pose_stamp_ = -1.0, localization_stamp_ = -1.0;
  bool localized_ = false;
  std::string why_not_localized_ = "no localization yet";
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Identity();
  wheelchair_core::Pose2D pose_;
  int unexpected_returns_ = 0;
  bool driver_fault_ = false;
  double driver_fault_since_ = 0.0;
  std::string driver_detail_;
  bool user_stop_ = false;
  SafetyVerdict latched_;
};

}  // namespace wheelchair_safety
