// Wheel odometry of the axle centre P (base_link) from the motor controller's encoder counts.
#pragma once

#include <wheelchair_base_driver/protocol.h>

namespace wheelchair_base_driver {

struct WheelGeometry {
  double wheel_radius = 0.0;   ///< r [m]
  double half_track = 0.0;     ///< b [m]
  double counts_per_rev = 0;   ///< encoder counts per wheel revolution
  double max_wheel_rate = 40;  ///< [rad/s]: faster increments are implausible and rejected
};

struct Twist2D {
  double v = 0.0;      ///< forward speed of P [m/s]
  double omega = 0.0;  ///< yaw rate [rad/s]
};

/// Eq. 10-11 of the paper (q_dot = S(q) eta) restricted to P: v = r (psi_r_dot + psi_l_dot) / 2,
/// omega = r (psi_r_dot - psi_l_dot) / (2 b).
Twist2D bodyTwistFromWheelRates(double left_rate, double right_rate, const WheelGeometry& g);

struct OdometryState {
  double x = 0.0, y = 0.0, theta = 0.0;        ///< pose of base_link in odom
  double v = 0.0, omega = 0.0;                 ///< body twist
  double left_angle = 0.0, right_angle = 0.0;  ///< accumulated wheel angles [rad]
  double left_rate = 0.0, right_rate = 0.0;    ///< [rad/s]
  double stamp = -1.0;                         ///< time of the last update, -1 before any
};

class EncoderOdometry {
 public:
  explicit EncoderOdometry(const WheelGeometry& geometry) : geometry_(geometry) {}
  /// Integrates one encoder sample taken at `stamp`. The first sample (and the first after
  /// resync()) only sets the reference. Returns false, and resyncs, when the increment would
  /// need a wheel faster than max_wheel_rate.
  bool update(const protocol::EncoderCounts& counts, double stamp);
  /// Forget the reference counts (pose is kept): the next sample starts a new increment.
  void resync() { has_reference_ = false; }
  const OdometryState& state() const { return state_; }

 private:
  WheelGeometry geometry_;
  bool has_reference_ = false;
  protocol::EncoderCounts reference_;
  OdometryState state_;
};

}  // namespace wheelchair_base_driver
