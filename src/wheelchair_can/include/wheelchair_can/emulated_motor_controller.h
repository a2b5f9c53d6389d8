// The chair's motor controller in software: speaks the protocol on the motor side of a
// transport and drives a MotorPlant (the simulator's wheels, or a trivial plant in tests).
//  - applies the commanded torques (saturated to max_torque) only when the command enables and
//    releases the brake, nothing is faulty, and the driver is alive;
//  - no valid torque command for command_timeout or no driver heartbeat for driver_timeout ->
//    zero torque + brake, fault bit latched until a command with the brake set arrives;
//  - a drive command whose time tag is older than command_timeout (on the transport's clock,
//    the bus clock both ends share) is ignored and latches kFaultStaleCommand: a command
//    delayed in a queue, or decided by a driver whose clock stood still, never moves the wheels;
//  - an undecodable torque frame is dropped and reported (kFaultBadCommand) without braking:
//    the last valid command goes on under the watchdog, the driver ends the drive;
//  - sends encoder counts + status at 100 Hz and a heartbeat at 20 Hz.
// Fault injection for the single-fault tests: power removed (silent, spring brakes on, restarts
// as from power-up), one wheel's encoder frozen, fault bits reported by the output stage.
#pragma once

#include <wheelchair_can/motor_plant.h>
#include <wheelchair_can/protocol.h>
#include <wheelchair_can/sequence_tracker.h>
#include <wheelchair_can/transport.h>

#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_core {
class ConfigReader;
}

namespace wheelchair_can {

struct EmulatedControllerConfig {
  double counts_per_rev = 4096;
  double max_torque = protocol::kMaxEncodableTorque;  ///< [N m] saturation per wheel
  double encoder_period = 0.01;
  double heartbeat_period = 0.05;
  double command_timeout = 0.1;
  double driver_timeout = 0.2;

  /// "" if usable, else every problem (wheelchair_core::ConfigChecks).
  std::string validate() const;
};

/// The one key a host of the emulated controller exposes: counts_per_rev (it must match the
/// driver's). The periods and timeouts are the protocol's (README), the torque limit the chair's.
void readEmulatedControllerConfig(wheelchair_core::ConfigReader& reader,
                                  EmulatedControllerConfig& config);

struct EmulatedControllerStats {
  std::uint64_t commands = 0;               ///< valid torque commands received
  std::uint64_t commands_lost = 0;          ///< sequence gaps
  std::uint64_t commands_out_of_order = 0;  ///< duplicated or reordered (ignored)
  std::uint64_t commands_stale = 0;         ///< drive commands older than command_timeout
  std::uint64_t decode_errors = 0;
  std::uint64_t frames_sent = 0;
  std::uint64_t timeouts = 0;  ///< command or driver heartbeat silences
};

class EmulatedMotorController {
 public:
  /// Throws std::invalid_argument if `config` is not valid.
  EmulatedMotorController(const EmulatedControllerConfig& config, CanTransport& transport,
                          MotorPlant& plant);
  /// Reads the bus, updates the watchdogs, applies torques to the plant, sends due frames.
  void step(double now);
  /// While silent nothing is sent (a dead controller, for heartbeat-loss tests).
  void setSilent(bool silent) { silent_ = silent; }
  /// Extra fault bits to report (added to the plant's own).
  void setInjectedFaults(std::uint16_t faults) { injected_faults_ = faults; }
  /// Power removed (false): nothing is read or sent, zero torque, the (spring-applied) parking
  /// brakes hold; power back (true): starts as from power-up (command-timeout fault latched).
  void setPowered(bool powered);
  bool powered() const { return powered_; }
  /// The encoder of a wheel stops counting (reports the count it had): a sensor failure.
  void freezeEncoders(bool left, bool right);

  /// Every fault bit reported (latched, injected, the plant's).
  std::uint16_t faults() const;
  /// The faults that brake (all but kReportOnlyFaults).
  std::uint16_t brakingFaults() const;
  protocol::ControllerState state() const;
  /// The torques last applied to the plant and whether the brake was set.
  double appliedLeft() const { return applied_left_; }
  double appliedRight() const { return applied_right_; }
  bool braking() const { return applied_brake_; }
  const EmulatedControllerStats& stats() const { return stats_; }
  const protocol::TorqueCommand& lastCommand() const { return command_; }

 private:
  void handleFrame(const CanFrame& frame, double now);
  void send(const protocol::Message& message);

  EmulatedControllerConfig config_;
  CanTransport& transport_;
  MotorPlant& plant_;
  std::vector<CanFrame> rx_;
  bool silent_ = false;
  bool powered_ = true;
  bool frozen_left_ = false, frozen_right_ = false;
  std::uint32_t frozen_left_count_ = 0, frozen_right_count_ = 0, last_left_count_ = 0,
                last_right_count_ = 0;
  std::uint16_t injected_faults_ = 0;
  std::uint16_t latched_faults_ = protocol::kFaultCommandTimeout;  // armed by a brake command
  bool has_command_ = false;
  double last_command_time_ = 0.0;
  bool has_driver_heartbeat_ = false;
  double last_driver_heartbeat_ = 0.0;
  protocol::TorqueCommand command_;
  SequenceTracker command_sequence_;
  double applied_left_ = 0.0, applied_right_ = 0.0;
  bool applied_brake_ = true;
  double next_encoder_time_ = -1e300, next_heartbeat_time_ = -1e300;
  std::uint8_t encoder_sequence_ = 0, status_sequence_ = 0, heartbeat_counter_ = 0;
  EmulatedControllerStats stats_;
};

}  // namespace wheelchair_can
