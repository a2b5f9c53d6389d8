#include <wheelchair_sim/wheel_odometry.h>

#include <cmath>

namespace wheelchair_sim {

namespace core = wheelchair_core;

WheelOdometry::WheelOdometry(const wheelchair_description::ChairParams& chair,
                             const SimParams& params, uint64_t seed)
    : radius_right_(chair.wheel_radius * (1.0 + params.odom_radius_error_right)),
      radius_left_(chair.wheel_radius * (1.0 + params.odom_radius_error_left)),
      half_track_(chair.half_track * (1.0 + params.odom_track_error)),
      noise_(params.odom_noise),
      rng_(seed) {}

void WheelOdometry::reset(const core::Pose2D& pose, const Eigen::Vector2d& wheel_angles) {
  pose_ = pose;
  last_angles_ = wheel_angles;
  velocity_ = core::BodyTwist();
}

void WheelOdometry::update(const Eigen::Vector2d& wheel_angles, double dt) {
  const Eigen::Vector2d dpsi = wheel_angles - last_angles_;
  last_angles_ = wheel_angles;
  // Each wheel's travel with the radius the odometry assumes for it.
  double travel_r = radius_right_ * dpsi(0);
  double travel_l = radius_left_ * dpsi(1);
  if (noise_ > 0.0) {
    std::normal_distribution<double> normal(0.0, 1.0);
    travel_r += noise_ * std::sqrt(std::abs(travel_r)) * normal(rng_);
    travel_l += noise_ * std::sqrt(std::abs(travel_l)) * normal(rng_);
  }
  const core::BodyMotion motion = core::bodyMotion(travel_r, travel_l, half_track_);
  pose_ = core::integrateArc(pose_, motion);
  if (dt > 0.0) velocity_ = {motion.distance / dt, motion.turn / dt};
}

}  // namespace wheelchair_sim
