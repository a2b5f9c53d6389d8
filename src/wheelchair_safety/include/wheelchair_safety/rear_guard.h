// The guard behind the chair (issue 24): while the path being driven backs up within the watched
// stretch ahead (stop_distance of travel: wheelchair_core/path_direction.h says which pieces back
// up), the rear laser must be live - no reverse motion at all while it is silent - and nothing
// unmapped may be in the corridor the body's rear sweeps within rear_stop_distance of reverse
// travel. The protective field ahead (the supervisor's front laser check) is the same idea in
// front of the chair; this one has its own file and sensor.
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_safety/safety_limits.h>

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace wheelchair_safety {

struct SafetyVerdict;

class RearGuard {
 public:
  explicit RearGuard(const SafetyLimits& limits) : limits_(limits) {}

  /// The path being driven (map frame, a pose's yaw is the chair's heading).
  void onPath(const std::vector<wheelchair_core::Pose2D>& path);
  /// A rear laser scan's returns in the map frame with the chair at `pose`; `mapped(point)` is
  /// true for a return on a mapped obstacle. Non-finite points are ignored.
  void onScan(double stamp, const std::vector<Eigen::Vector2d>& returns_in_map,
              const wheelchair_core::Pose2D& pose,
              const std::function<bool(const Eigen::Vector2d&)>& mapped);

  /// True if the path backs up within stop_distance of travel from the vertex nearest `pose`.
  bool reversingAhead(const wheelchair_core::Pose2D& pose) const;
  /// The rear guard's verdict at `now` with the chair at `pose`: kRearSensorSilent, kObstacleBehind
  /// or no stop.
  SafetyVerdict evaluate(double now, const wheelchair_core::Pose2D& pose) const;

 private:
  /// Index of the path vertex nearest `here`.
  size_t nearestVertex(const Eigen::Vector2d& here) const;
  /// True if `point` lies within corridor_half_width of a reverse step of the path within
  /// rear_overhang + rear_stop_distance of travel from the chair.
  bool inReverseCorridor(const Eigen::Vector2d& point, const wheelchair_core::Pose2D& pose) const;

  SafetyLimits limits_;
  std::vector<Eigen::Vector2d> path_;
  std::vector<bool> reverse_step_;  ///< per step i -> i + 1 of the path: driven in reverse
  double scan_stamp_ = -1.0;
  int unexpected_returns_ = 0;
};

}  // namespace wheelchair_safety
