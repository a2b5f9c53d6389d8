#include <wheelchair_core/path_direction.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_safety/rear_guard.h>
#include <wheelchair_safety/safety_supervisor.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace wheelchair_safety {

void RearGuard::onPath(const std::vector<wheelchair_core::Pose2D>& path) {
  path_.clear();
  for (const auto& pose : path) path_.push_back(pose.position());
  reverse_step_.assign(path_.size() > 0 ? path_.size() - 1 : 0, false);
  for (const wheelchair_core::PathPiece& piece : wheelchair_core::splitAtCusps(path))
    if (piece.direction == wheelchair_core::Direction::kReverse)
      for (size_t i = piece.begin; i < piece.end; ++i) reverse_step_[i] = true;
  unexpected_returns_ = 0;
}

size_t RearGuard::nearestVertex(const Eigen::Vector2d& here) const {
  size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < path_.size(); ++i) {
    const double d = (path_[i] - here).squaredNorm();
    if (d < best) best = d, nearest = i;
  }
  return nearest;
}

bool RearGuard::reversingAhead(const wheelchair_core::Pose2D& pose) const {
  if (reverse_step_.empty()) return false;
  double travelled = 0.0;
  for (size_t i = nearestVertex(pose.position());
       i < reverse_step_.size() && travelled <= limits_.stop_distance; ++i) {
    if (reverse_step_[i]) return true;
    travelled += (path_[i + 1] - path_[i]).norm();
  }
  return false;
}

bool RearGuard::inReverseCorridor(const Eigen::Vector2d& point,
                                  const wheelchair_core::Pose2D& pose) const {
  // The axle follows the path; the body's rear is rear_overhang behind it, so what lies on the
  // path within rear_overhang + rear_stop_distance of reverse travel is what the rear reaches
  // within rear_stop_distance.
  const double reach = limits_.rear_overhang + limits_.rear_stop_distance;
  Eigen::Vector2d from = pose.position();
  double walked = 0.0;
  size_t i = nearestVertex(from);
  for (; i < reverse_step_.size() && walked <= reach; ++i) {
    const Eigen::Vector2d& to = path_[i + 1];
    double along = 0.0;
    const double dist = wheelchair_core::pointSegmentDistance(point, from, to, &along);
    if (reverse_step_[i] && dist <= limits_.corridor_half_width && walked + along <= reach)
      return true;
    walked += (to - from).norm();
    from = to;
  }
  // The path ends backing up: the rear reaches rear_overhang beyond its last axle position, so
  // the corridor goes on straight behind it.
  if (i == reverse_step_.size() && walked < reach && reverse_step_.back()) {
    const Eigen::Vector2d step = path_.back() - path_[path_.size() - 2];
    if (step.norm() > 1e-9) {
      const Eigen::Vector2d beyond = path_.back() + step.normalized() * (reach - walked);
      return wheelchair_core::pointSegmentDistance(point, path_.back(), beyond) <=
             limits_.corridor_half_width;
    }
  }
  return false;
}

void RearGuard::onScan(double stamp, const std::vector<Eigen::Vector2d>& returns_in_map,
                       const wheelchair_core::Pose2D& pose,
                       const std::function<bool(const Eigen::Vector2d&)>& mapped) {
  scan_stamp_ = stamp;
  unexpected_returns_ = 0;
  if (reverse_step_.empty()) return;
  for (const auto& point : returns_in_map)
    if (point.allFinite() && inReverseCorridor(point, pose) && !mapped(point))
      ++unexpected_returns_;
}

SafetyVerdict RearGuard::evaluate(double now, const wheelchair_core::Pose2D& pose) const {
  if (!reversingAhead(pose)) return {};
  if (scan_stamp_ < 0.0)
    return {true, StopReason::kRearSensorSilent, "no rear laser scan yet and the path backs up",
            NAN, limits_.rear_scan_timeout};
  const double age = now - scan_stamp_;
  if (age > limits_.rear_scan_timeout) {
    char text[96];
    std::snprintf(text, sizeof(text), "no rear laser scan for %.2f s and the path backs up", age);
    return {true, StopReason::kRearSensorSilent, text, age, limits_.rear_scan_timeout};
  }
  if (unexpected_returns_ >= limits_.min_obstacle_returns)
    return {true, StopReason::kObstacleBehind,
            std::to_string(unexpected_returns_) + " rear laser returns on the path behind",
            static_cast<double>(unexpected_returns_),
            static_cast<double>(limits_.min_obstacle_returns)};
  return {};
}

}  // namespace wheelchair_safety
