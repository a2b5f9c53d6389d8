// Wheel speeds eta = [psi_r_dot, psi_l_dot] from encoder angles: the closed-loop simulation's
// odometry (test support; the nodelet takes them from /odom's twist).
#pragma once

#include <Eigen/Core>

namespace wheelchair_controller {

/// From encoder angles: finite difference over consecutive readings, then a first-order
/// low-pass with time constant `time_constant` (0: none). A reading that goes back in time or
/// is non-finite resets the estimator.
class WheelSpeedEstimator {
 public:
  explicit WheelSpeedEstimator(double time_constant = 0.0) : time_constant_(time_constant) {}
  /// Returns the current estimate (zero until two readings arrived).
  Eigen::Vector2d update(double stamp, const Eigen::Vector2d& wheel_angles);
  const Eigen::Vector2d& estimate() const { return eta_; }

 private:
  double time_constant_;
  bool have_last_ = false;
  double last_stamp_ = 0.0;
  Eigen::Vector2d last_angles_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d eta_ = Eigen::Vector2d::Zero();
};

}  // namespace wheelchair_controller
