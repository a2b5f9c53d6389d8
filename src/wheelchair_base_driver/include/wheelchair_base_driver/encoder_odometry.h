// Wheel odometry of the axle centre P (base_link) from the motor controller's encoder counts,
// with the chair's kinematics of wheelchair_core (the paper's eq. 10-11 and the exact arc).
#pragma once

#include <wheelchair_can/protocol.h>
#include <wheelchair_core/kinematics.h>
#include <wheelchair_core/pose2d.h>

namespace wheelchair_base_driver {

struct WheelGeometry {
  double wheel_radius = 0.0;     ///< r [m] (the chair file's)
  double half_track = 0.0;       ///< b [m] (the chair file's)
  double counts_per_rev = 4096;  ///< encoder counts per wheel revolution
  double max_wheel_rate = 40;    ///< [rad/s]: faster increments are implausible and rejected

  wheelchair_core::WheelBase base() const { return {wheel_radius, half_track}; }
};

struct OdometryState {
  wheelchair_core::Pose2D pose;                ///< base_link in odom
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
  bool update(const wheelchair_can::protocol::EncoderCounts& counts, double stamp);
  /// Forget the reference counts (pose is kept): the next sample starts a new increment.
  void resync() { has_reference_ = false; }
  const OdometryState& state() const { return state_; }

 private:
  WheelGeometry geometry_;
  bool has_reference_ = false;
  wheelchair_can::protocol::EncoderCounts reference_;
  OdometryState state_;
};

}  // namespace wheelchair_base_driver
