// What the driver core needs to know: the chair's wheels and encoders, its torque and speed
// limits, the command and heartbeat rates, the watchdogs (commands, permits, the motor
// controller on the bus clock and on the wall clock) and the checks that latch a stop. One
// parameter pattern (wheelchair_core/config.h): defaults here, validate(), and the keys in
// readDriverConfig.
#pragma once

#include <wheelchair_base_driver/encoder_odometry.h>

#include <string>

namespace wheelchair_core {
class ConfigReader;
}

namespace wheelchair_base_driver {

struct DriverConfig {
  WheelGeometry geometry;
  /// [N m] per wheel; larger |torque| is rejected. The nodelet starts from the chair file's
  /// max_wheel_torque.
  double max_torque = 0.0;
  double command_period = 0.01;     ///< torque frames are repeated at this period (100 Hz)
  double heartbeat_period = 0.05;   ///< driver heartbeat period (20 Hz)
  double command_timeout = 0.1;     ///< torque message watchdog [s]
  double controller_timeout = 0.2;  ///< MC heartbeat watchdog [s]
  /// [m/s] the chair's limit (the chair file's max_speed): faster latches a stop; torque that
  /// would speed it up further is cut.
  double max_speed = 0.0;
  /// [s] a permit of the safety supervisor is fresh this long (its check period is 20 ms).
  double permit_timeout = 0.1;
  /// [m/s^2] the supervisor's speed limit (carried by its permit) as the driver holds it: a rise
  /// at once, a fall no faster than this from the speed at the fall (the controlled stop's
  /// 0.5 m/s^2: the controller slows down with the limit, the driver does not jolt it).
  double speed_limit_decel = 0.5;
  /// [m/s] above the held limit by this much, torque that would speed the chair up is cut; by
  /// twice this much for 0.1 s (it did not slow down with the limit): a latched stop.
  double speed_limit_tolerance = 0.05;
  /// [s] the longest controlled stop the controller may run after a stop that leaves the command
  /// path intact (the supervisor's, a foreign command, a corrupted stream), then the brake: from
  /// 1.5 m/s at 0.5 m/s^2 with jerk-limited ramps about 3.5 s.
  double stop_window = 4.0;
  /// [s of wall time] the MC's heartbeats may stop this long while driving before a latched stop
  /// (the bus clock may stand still with the process that owns it: a stopped simulator).
  double controller_wall_timeout = 1.0;
  /// A wheel whose count does not change for encoder_check_time [s] while the other turns faster
  /// than encoder_check_rate [rad/s] during a drive has a failed encoder: latched stop.
  double encoder_check_time = 0.3;
  double encoder_check_rate = 1.0;
  /// [rad] ... or while the other wheel turns this far faster than encoder_check_rate on average
  /// (at 0.7 m/s about 0.05 s and 4 cm of travel: a bounded distance, not only a time, whatever
  /// the speed; a slow turn about a standing inner wheel is no fault).
  double encoder_check_angle = 0.25;
  /// [N m] ... both only while that wheel's motor pushes it at least this hard (either sign): a
  /// drive needs < 6 N m per wheel (rolling resistance 1.7, 0.35 m/s^2 of the chair's mass 4.1),
  /// so a wheel standing under less is the chair turning about it, not a failed encoder; with a
  /// frozen encoder the controller pushes the standing wheel far harder at once.
  double encoder_check_torque = 12.0;
  /// [N m] a wheel commanded at least this torque (either sign) that does not count for
  /// stall_time [s] (both encoders dead, a motor or gearbox disconnected, a blocked wheel), or
  /// that turns faster than encoder_check_rate against it and speeds up (an encoder wired
  /// backwards, a runaway), has failed: latched stop. Braking against the motion slows the
  /// wheel and is not a fault.
  double stall_torque = 20.0;
  double stall_time = 0.4;

  /// "" if usable, else every problem, each naming its value.
  std::string validate() const;
};

/// Keys: counts_per_rev, max_wheel_rate, max_torque, max_speed, command_rate [Hz]
/// (1 / command_period), command_timeout, controller_timeout, permit_timeout,
/// speed_limit_decel, speed_limit_tolerance, stop_window,
/// controller_wall_timeout, encoder_check_time, encoder_check_rate, encoder_check_angle,
/// encoder_check_torque,
/// stall_torque, stall_time. The wheel radius and half
/// track are not keys: they are the chair file's.
void readDriverConfig(wheelchair_core::ConfigReader& reader, DriverConfig& config);

}  // namespace wheelchair_base_driver
