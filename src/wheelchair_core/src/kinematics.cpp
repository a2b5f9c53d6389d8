#include <wheelchair_core/kinematics.h>

#include <cmath>

namespace wheelchair_core {

BodyTwist bodyTwist(const WheelRates& rates, const WheelBase& base) {
  return {0.5 * base.wheel_radius * (rates.right + rates.left),
          0.5 * base.wheel_radius * (rates.right - rates.left) / base.half_track};
}

WheelRates wheelRates(const BodyTwist& twist, const WheelBase& base) {
  const double bw = base.half_track * twist.omega;
  return {(twist.v + bw) / base.wheel_radius, (twist.v - bw) / base.wheel_radius};
}

BodyMotion bodyMotion(double travel_right, double travel_left, double half_track) {
  return {0.5 * (travel_right + travel_left), 0.5 * (travel_right - travel_left) / half_track};
}

Pose2D integrateArc(const Pose2D& pose, const BodyMotion& motion) {
  const double half = 0.5 * motion.turn;
  const double chord =
      std::abs(half) < 1e-9 ? motion.distance : motion.distance * std::sin(half) / half;
  const double heading = pose.yaw + half;
  return {pose.x + chord * std::cos(heading), pose.y + chord * std::sin(heading),
          normalizeAngle(pose.yaw + motion.turn)};
}

}  // namespace wheelchair_core
