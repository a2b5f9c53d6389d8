// The one way every fault ends: decelerate within the comfort limits using wheel odometry only
// (the pose may be what failed), then zero torque and the parking brake.
#pragma once

#include <wheelchair_controller/linearization.h>
#include <wheelchair_controller/motion_profile.h>

namespace wheelchair_controller {

struct StopConfig {
  MotionLimits linear{0.8, 0.5, 1.0};   ///< deceleration/jerk limits of the forward speed
  MotionLimits angular{0.8, 1.0, 2.0};  ///< deceleration/jerk limits of the yaw rate
  double velocity_gain = 10.0;          ///< [1/s] wheel-speed tracking of the ramp
  double rest_speed = 0.003;            ///< [m/s] rim speed below which the brake engages
  double extra_time = 2.0;              ///< [s] brake anyway this long after the ramp's end
  bool compensate_rolling_resistance = true;
};

struct WheelCommand {
  Eigen::Vector2d torque = Eigen::Vector2d::Zero();  ///< [tau_r, tau_l] N m
  bool brake = true;
};

class ControlledStop {
 public:
  ControlledStop(const ChairParams& chair, const StopConfig& config);

  /// Starts from the measured wheel speeds eta and the current body acceleration (a, w_dot)
  /// (zero if unknown), so the deceleration begins without a step in acceleration.
  void start(const Eigen::Vector2d& eta, double accel = 0.0, double yaw_accel = 0.0);
  /// One step of length dt with the measured wheel speeds (non-finite: brake at once).
  WheelCommand step(const Eigen::Vector2d& eta, double dt);
  bool finished() const { return finished_; }

 private:
  ChairParams chair_;
  StopConfig config_;
  ProfileSample linear_, angular_;
  double elapsed_ = 0.0, deadline_ = 0.0;
  bool finished_ = true;
};

}  // namespace wheelchair_controller
