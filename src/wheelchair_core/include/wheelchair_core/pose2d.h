// A planar pose (x, y, yaw) and the few operations every package needs on it: the one pose
// type of the project (map, odom and base_link poses, sensor mounts, plan poses).
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace wheelchair_core {

struct Pose2D {
  double x = 0.0;    ///< [m]
  double y = 0.0;    ///< [m]
  double yaw = 0.0;  ///< [rad], counter-clockwise from the x axis

  Eigen::Vector2d position() const { return {x, y}; }
  bool isFinite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(yaw); }
};

/// `angle` wrapped into [-pi, pi].
inline double normalizeAngle(double angle) { return std::remainder(angle, 2.0 * M_PI); }

/// The signed smallest rotation from `from` to `to`, in [-pi, pi].
inline double angleDifference(double to, double from) { return normalizeAngle(to - from); }

/// `b` given in the frame of `a`, expressed in a's parent frame (a ⊕ b).
inline Pose2D compose(const Pose2D& a, const Pose2D& b) {
  const double c = std::cos(a.yaw), s = std::sin(a.yaw);
  return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, normalizeAngle(a.yaw + b.yaw)};
}

/// The pose of the parent frame seen from `a` (⊖a).
inline Pose2D inverse(const Pose2D& a) {
  const double c = std::cos(a.yaw), s = std::sin(a.yaw);
  return {-c * a.x - s * a.y, s * a.x - c * a.y, normalizeAngle(-a.yaw)};
}

/// `b` seen from `a` (⊖a ⊕ b): the relative motion between two poses of one trajectory.
inline Pose2D between(const Pose2D& a, const Pose2D& b) { return compose(inverse(a), b); }

/// A point given in the frame of `pose`, expressed in the pose's parent frame.
inline Eigen::Vector2d transformPoint(const Pose2D& pose, const Eigen::Vector2d& p) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  return {pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y()};
}

}  // namespace wheelchair_core
