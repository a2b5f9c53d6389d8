#include <wheelchair_core/polygon.h>
#include <wheelchair_safety/safety_supervisor.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wheelchair_safety {
namespace {

SafetyVerdict stopFor(StopReason reason, std::string detail, double value = NAN,
                      double limit = NAN) {
  return {true, reason, std::move(detail), value, limit};
}

std::string seconds(const char* what, double age) {
  char text[96];
  std::snprintf(text, sizeof(text), "%s for %.2f s", what, age);
  return text;
}

}  // namespace

const char* describe(StopReason reason) {
  switch (reason) {
    case StopReason::kNone:
      return "safe";
    case StopReason::kNoData:
      return "waiting for sensors";
    case StopReason::kLocalizationLost:
      return "the chair does not know where it is";
    case StopReason::kCovarianceTooLarge:
      return "the position estimate is too uncertain";
    case StopReason::kLaserSilent:
      return "the laser scanner is silent";
    case StopReason::kPoseStale:
      return "the position is out of date";
    case StopReason::kUnexpectedObstacle:
      return "something is in the way";
    case StopReason::kDriverFault:
      return "the motor controller reports a fault";
    case StopReason::kUserStop:
      return "stopped by the rider";
    case StopReason::kRearSensorSilent:
      return "the sensor behind the chair is silent";
    case StopReason::kObstacleBehind:
      return "something is behind the chair";
  }
  return "unknown";
}

SafetySupervisor::SafetySupervisor(SafetyLimits limits, ProtectiveField field)
    : limits_(limits), field_(field), rear_(limits) {}

void SafetySupervisor::onMap(const wheelchair_core::OccupancyMap& map) { map_ = map; }

void SafetySupervisor::onPath(const std::vector<wheelchair_core::Pose2D>& path) {
  path_.clear();
  for (const auto& pose : path) path_.push_back(pose.position());
  rear_.onPath(path);
}

void SafetySupervisor::onLocalization(double stamp, bool localized,
                                      const Eigen::Matrix3d& covariance,
                                      const std::string& why_not) {
  localization_stamp_ = stamp;
  localized_ = localized && covariance.allFinite();
  why_not_localized_ = covariance.allFinite() ? why_not : "non-finite covariance";
  if (covariance.allFinite()) covariance_ = covariance;
}

void SafetySupervisor::onPose(double stamp, const wheelchair_core::Pose2D& pose) {
  if (!pose.isFinite()) return;  // a non-finite pose never refreshes the watchdog
  pose_stamp_ = stamp;
  pose_ = pose;
}

void SafetySupervisor::onScan(double stamp, const std::vector<Eigen::Vector2d>& returns_in_map) {
  scan_stamp_ = stamp;
  unexpected_returns_ = 0;
  nearest_unexpected_ = INFINITY;
  obstacle_limit_ = SpeedLimit();
  if (path_.empty()) return;
  const double stop_extent = stopExtent();
  const double slow_extent = stop_extent + field_.slowdown_length;
  const auto ahead = pathAhead(path_, pose_.position(), slow_extent);
  std::vector<double> slowdown;  // along-path distances of returns in the slow-down zone
  for (const auto& point : returns_in_map) {
    if (!point.allFinite()) continue;
    const double s = distanceAlongCorridor(ahead, point, limits_.corridor_half_width);
    if (s > slow_extent || knownObstacleNear(point)) continue;
    if (s <= stop_extent) {
      ++unexpected_returns_;
      nearest_unexpected_ = std::min(nearest_unexpected_, s);
    } else {
      slowdown.push_back(s);
    }
  }
  const size_t needed = static_cast<size_t>(limits_.min_obstacle_returns);
  if (slowdown.size() >= needed) {
    // The needed-th nearest: fewer returns than an obstacle takes are noise, as in the stop zone.
    std::nth_element(slowdown.begin(), slowdown.begin() + (needed - 1), slowdown.end());
    const double s = slowdown[needed - 1];
    char text[96];
    std::snprintf(text, sizeof(text), "something %.2f m ahead of the front",
                  s - field_.front_offset);
    obstacle_limit_ = {field_.maxStoppableSpeed(s - field_.front_offset), text};
  }
}

void SafetySupervisor::onLaserView(const wheelchair_core::LaserScan2D& scan,
                                   const wheelchair_core::Pose2D& laser_in_map) {
  view_limit_ = SpeedLimit();
  if (path_.empty() || !laser_in_map.isFinite()) return;
  const double wanted = stopExtent() + field_.slowdown_length;
  const auto ahead = pathAhead(path_, pose_.position(), wanted);
  double length = 0.0;
  for (size_t i = 0; i + 1 < ahead.size(); ++i) length += (ahead[i + 1] - ahead[i]).norm();
  const char* why = nullptr;
  const double seen =
      visibleLength(ahead, scan, laser_in_map, field_.front_offset, field_.view_tolerance, &why);
  if (seen >= length - 1e-9) return;  // sees all it needs, or the path to its end
  char text[160];
  std::snprintf(text, sizeof(text),
                "the laser sees %.2f m of the path ahead of the front (then %s)",
                std::max(0.0, seen - field_.front_offset), why ? why : "?");
  view_limit_ = {field_.maxStoppableSpeed(seen - field_.front_offset), text};
}

void SafetySupervisor::onSpeed(double, double forward_speed) {
  if (std::isfinite(forward_speed)) speed_ = std::abs(forward_speed);
}

double SafetySupervisor::stopExtent() const {
  return std::max(limits_.stop_distance, field_.front_offset + field_.stopDistance(speed_));
}

SpeedLimit SafetySupervisor::speedLimit() const {
  if (latched_.stop) return {0.0, "stopped: " + latched_.detail};
  return obstacle_limit_.speed <= view_limit_.speed ? obstacle_limit_ : view_limit_;
}

void SafetySupervisor::onRearScan(double stamp,
                                  const std::vector<Eigen::Vector2d>& returns_in_map) {
  rear_.onScan(stamp, returns_in_map, pose_,
               [this](const Eigen::Vector2d& p) { return knownObstacleNear(p); });
}

void SafetySupervisor::onDriverStatus(double stamp, bool fault, const std::string& detail) {
  if (fault && !driver_fault_) driver_fault_since_ = stamp;
  driver_fault_ = fault;
  driver_detail_ = detail;
}

void SafetySupervisor::onUserStop(double) { user_stop_ = true; }

void SafetySupervisor::onUserCommand(double) {
  user_stop_ = false;
  latched_ = SafetyVerdict();
  // The rider's release reaches the driver first (the drive channel), so the driver's fault or
  // latch this record holds is released too: kept, it would latch this stop again at the next
  // check, before the driver's report of its release arrives. A fault that still holds is
  // reported again by the driver (its first report after a release is always sent).
  driver_fault_ = false;
}

bool SafetySupervisor::knownObstacleNear(const Eigen::Vector2d& point) const {
  int cx, cy;
  if (map_.width == 0 || !map_.worldToCell(point.x(), point.y(), cx, cy))
    return map_.width != 0;  // outside the map is not "the path ahead"; no map: unknown
  const int reach = static_cast<int>(std::ceil(limits_.map_tolerance / map_.resolution));
  for (int dy = -reach; dy <= reach; ++dy)
    for (int dx = -reach; dx <= reach; ++dx)
      if (map_.inBounds(cx + dx, cy + dy) &&
          map_.at(cx + dx, cy + dy) >= 50)  // occupied in the nav_msgs convention
        return true;
  return false;
}

SafetyVerdict SafetySupervisor::evaluateLocalization(double now) const {
  if (now - localization_stamp_ > limits_.localization_timeout)
    return stopFor(StopReason::kLocalizationLost,
                   seconds("no localization status", now - localization_stamp_),
                   now - localization_stamp_, limits_.localization_timeout);
  if (!localized_) return stopFor(StopReason::kLocalizationLost, why_not_localized_);
  const double xy_std =
      std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(covariance_.topLeftCorner<2, 2>())
                    .eigenvalues()
                    .maxCoeff());
  const double heading_std = std::sqrt(std::max(0.0, covariance_(2, 2)));
  if (xy_std > limits_.max_position_std || heading_std > limits_.max_heading_std) {
    char text[96];
    std::snprintf(text, sizeof(text), "position std %.2f m, heading std %.2f rad", xy_std,
                  heading_std);
    const bool position = xy_std > limits_.max_position_std;
    return stopFor(StopReason::kCovarianceTooLarge, text, position ? xy_std : heading_std,
                   position ? limits_.max_position_std : limits_.max_heading_std);
  }
  return {};
}

SafetyVerdict SafetySupervisor::evaluate(double now) const {
  if (user_stop_) return stopFor(StopReason::kUserStop, "switch pressed while driving");
  if (driver_fault_ && now - driver_fault_since_ >= limits_.driver_fault_grace)
    return stopFor(StopReason::kDriverFault, driver_detail_, now - driver_fault_since_,
                   limits_.driver_fault_grace);
  const bool localizer = limits_.require_localizer;
  if (scan_stamp_ < 0.0 || pose_stamp_ < 0.0 || (localizer && localization_stamp_ < 0.0))
    return stopFor(StopReason::kNoData, scan_stamp_ < 0.0   ? "no laser scan yet"
                                        : pose_stamp_ < 0.0 ? "no pose yet"
                                                            : "no localization status yet");
  if (now - scan_stamp_ > limits_.scan_timeout)
    return stopFor(StopReason::kLaserSilent, seconds("no laser scan", now - scan_stamp_),
                   now - scan_stamp_, limits_.scan_timeout);
  if (now - pose_stamp_ > limits_.pose_timeout)
    return stopFor(StopReason::kPoseStale, seconds("no pose update", now - pose_stamp_),
                   now - pose_stamp_, limits_.pose_timeout);
  if (localizer) {
    const SafetyVerdict lost = evaluateLocalization(now);
    if (lost.stop) return lost;
  }
  const SafetyVerdict behind = rear_.evaluate(now, pose_);
  if (behind.stop) return behind;
  if (unexpected_returns_ >= limits_.min_obstacle_returns) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "%d laser returns on the path ahead, nearest %.2f m from the axle, inside the "
                  "stop zone of %.2f m at %.2f m/s",
                  unexpected_returns_, nearest_unexpected_, stopExtent(), speed_);
    return stopFor(StopReason::kUnexpectedObstacle, text, unexpected_returns_,
                   limits_.min_obstacle_returns);
  }
  return {};
}

SafetyVerdict SafetySupervisor::check(double now) {
  if (latched_.stop) return latched_;
  const SafetyVerdict verdict = evaluate(now);
  // Waiting for the first data is a state, not an event: nothing has moved yet.
  if (verdict.stop && verdict.reason != StopReason::kNoData) latched_ = verdict;
  return verdict;
}

}  // namespace wheelchair_safety
