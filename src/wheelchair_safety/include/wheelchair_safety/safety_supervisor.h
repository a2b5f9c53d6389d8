// The safety supervisor: watches localization, the laser, tf, the path ahead and the base
// driver, and demands a stop (controlled deceleration, then the brake) with a reason the
// rider and the carers can read. A stop latches: the chair moves again only on a new command
// from the rider. ROS-free; time is injected (seconds, any epoch).
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>
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

class SafetySupervisor {
 public:
  explicit SafetySupervisor(SafetyLimits limits = SafetyLimits());

  void onMap(const wheelchair_core::OccupancyMap& map);
  /// The path being driven, in the map frame (empty: nothing ahead to watch).
  void onPath(const std::vector<wheelchair_core::Pose2D>& path);
  /// Localizer status: `localized` and the pose covariance (x, y, theta) in the map frame.
  void onLocalization(double stamp, bool localized, const Eigen::Matrix3d& covariance,
                      const std::string& why_not);
  /// The chair's pose (tf map -> base_link) and when it was valid.
  void onPose(double stamp, const wheelchair_core::Pose2D& pose);
  /// A laser scan's returns, already in the map frame; non-finite points are ignored.
  void onScan(double stamp, const std::vector<Eigen::Vector2d>& returns_in_map);
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

 private:
  SafetyVerdict evaluate(double now) const;
  bool knownObstacleNear(const Eigen::Vector2d& point) const;
  /// Distance from `point` to the path ahead of the chair, within stop_distance of travel.
  bool inCorridorAhead(const Eigen::Vector2d& point) const;

  SafetyLimits limits_;
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
