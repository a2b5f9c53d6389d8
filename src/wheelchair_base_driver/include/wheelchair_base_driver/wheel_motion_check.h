// Does each wheel move as its motor is told? ROS-free, time injected. While torque drives the
// chair (the caller resets it otherwise), a wheel has failed when
//  - its encoder does not count while its motor pushes it (|torque| >= encoder_check_torque)
//    and the other wheel turns faster than encoder_check_rate for encoder_check_time, or turns
//    encoder_check_angle (a frozen encoder: a bounded distance); standing under a light torque
//    while the other turns is the chair turning about that wheel;
//  - it is commanded |torque| >= stall_torque for stall_time and does not count (both encoders
//    dead, a motor or gearbox disconnected, a blocked wheel);
//  - it turns faster than encoder_check_rate against a commanded |torque| >= stall_torque for
//    stall_time and speeds up meanwhile (an encoder wired backwards: the controller pushes ever
//    harder; a runaway). Braking against the motion slows the wheel and is no fault.
#pragma once

#include <wheelchair_base_driver/driver_config.h>

#include <array>
#include <cmath>
#include <string>

namespace wheelchair_base_driver {

enum class WheelFault {
  kNone = 0,
  kFrozenEncoder,   ///< a wheel does not count while the other turns
  kStalled,         ///< torque applied, the wheel does not count
  kAgainstCommand,  ///< the wheel speeds up against its torque
};

struct WheelVerdict {
  WheelFault fault = WheelFault::kNone;
  std::string detail;  ///< which wheel, for how long / how far (for the log)
};

/// One wheel's commanded torque [N m] and measured angle [rad] and rate [rad/s].
struct WheelState {
  double torque = 0.0, angle = 0.0, rate = 0.0;
};

class WheelMotionCheck {
 public:
  explicit WheelMotionCheck(const DriverConfig& config) : config_(config) {}

  /// Not driving: a wheel standing still now says nothing about its encoder later.
  void reset(double now, double left_angle, double right_angle);
  /// An encoder frame at `stamp` with both wheels' angles.
  void onEncoder(double stamp, double left_angle, double right_angle);
  /// While driving (torques applied) and encoder frames arrive (`counting`): the first fault.
  WheelVerdict check(double now, bool counting, const WheelState& left, const WheelState& right);

 private:
  struct Wheel {
    double angle = NAN;           ///< at its last count
    double counted_at = NAN;      ///< [s] its last count
    double other_at_count = NAN;  ///< the other wheel's angle at its last count
    double pushed_since = NAN;    ///< [s] |torque| >= stall_torque since
    double against_since = NAN;   ///< [s] turning against |torque| >= stall_torque since
    double against_rate = 0.0;    ///< |rate| then
  };
  WheelVerdict checkWheel(const char* name, Wheel& wheel, const WheelState& state,
                          const WheelState& other, double now, bool counting);

  DriverConfig config_;
  std::array<Wheel, 2> wheels_;  ///< left, right
};

}  // namespace wheelchair_base_driver
