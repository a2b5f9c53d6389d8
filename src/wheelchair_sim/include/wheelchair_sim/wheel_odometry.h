// Dead reckoning from the wheel encoders as a base driver would do it (wheelchair_core's eq.
// 10-11 and exact arc), with the systematic errors of a mis-calibrated chair (each wheel's own
// wrong radius, a wrong track) and random wheel-travel errors.
#pragma once

#include <wheelchair_core/kinematics.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_sim/sim_params.h>

#include <Eigen/Core>

#include <random>

namespace wheelchair_sim {

class WheelOdometry {
 public:
  /// The odometry assumes radii r (1 + odom_radius_error_*) and half track
  /// b (1 + odom_track_error); each wheel's measured travel gets a Gaussian error of
  /// variance odom_noise^2 * |travel|.
  WheelOdometry(const wheelchair_description::ChairParams& chair, const SimParams& params,
                uint64_t seed);

  /// Starts dead reckoning at `pose` with the current encoder angles [right, left].
  void reset(const wheelchair_core::Pose2D& pose, const Eigen::Vector2d& wheel_angles);

  /// Integrates the encoder angles read `dt` seconds after the previous ones.
  void update(const Eigen::Vector2d& wheel_angles, double dt);

  const wheelchair_core::Pose2D& pose() const { return pose_; }  ///< in odom
  const wheelchair_core::BodyTwist& velocity() const { return velocity_; }

 private:
  double radius_right_, radius_left_, half_track_, noise_;
  wheelchair_core::Pose2D pose_;
  wheelchair_core::BodyTwist velocity_;
  Eigen::Vector2d last_angles_ = Eigen::Vector2d::Zero();
  std::mt19937_64 rng_;
};

}  // namespace wheelchair_sim
