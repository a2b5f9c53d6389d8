#include <wheelchair_can/emulated_motor_controller.h>
#include <wheelchair_core/config.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wheelchair_can {

namespace {
std::uint32_t angleToCounts(double angle, double counts_per_rev) {
  const auto counts =
      static_cast<std::int64_t>(std::llround(angle / (2.0 * M_PI) * counts_per_rev));
  return static_cast<std::uint32_t>(counts) & (protocol::kEncoderModulus - 1);
}
/// [s] a drive command may be tagged this far ahead of the controller's clock (the transports'
/// clocks are read at different moments); further ahead is a tag of a long-gone time that
/// wrapped (the tag repeats every 1.024 s).
constexpr double kFutureTolerance = 0.02;
/// Keeps a fixed period; after a late step the schedule restarts from `now`.
double nextDeadline(double deadline, double period, double now) {
  deadline += period;
  return deadline > now ? deadline : now + period;
}
}  // namespace

std::string EmulatedControllerConfig::validate() const {
  return wheelchair_core::ConfigChecks()
      .positive("counts_per_rev", counts_per_rev)
      .positive("max_torque", max_torque)
      .check(max_torque <= protocol::kMaxEncodableTorque,
             "max_torque exceeds the protocol's 327.67 N m")
      .positive("encoder_period", encoder_period)
      .positive("heartbeat_period", heartbeat_period)
      .positive("command_timeout", command_timeout)
      .positive("driver_timeout", driver_timeout)
      .result();
}

void readEmulatedControllerConfig(wheelchair_core::ConfigReader& reader,
                                  EmulatedControllerConfig& config) {
  reader.read("counts_per_rev", config.counts_per_rev);
}

EmulatedMotorController::EmulatedMotorController(const EmulatedControllerConfig& config,
                                                 CanTransport& transport, MotorPlant& plant)
    : config_(config), transport_(transport), plant_(plant) {
  const std::string problem = config_.validate();
  if (!problem.empty()) throw std::invalid_argument("emulated motor controller: " + problem);
}

std::uint16_t EmulatedMotorController::faults() const {
  return static_cast<std::uint16_t>(latched_faults_ | injected_faults_ | plant_.hardwareFaults());
}

std::uint16_t EmulatedMotorController::brakingFaults() const {
  return static_cast<std::uint16_t>(faults() & ~protocol::kReportOnlyFaults);
}

void EmulatedMotorController::setPowered(bool powered) {
  if (powered && !powered_) {  // power-up: as constructed
    latched_faults_ = protocol::kFaultCommandTimeout;
    has_command_ = has_driver_heartbeat_ = false;
    command_ = protocol::TorqueCommand();
    command_sequence_.reset();
    next_encoder_time_ = next_heartbeat_time_ = -1e300;
  }
  powered_ = powered;
}

void EmulatedMotorController::freezeEncoders(bool left, bool right) {
  if (left && !frozen_left_) frozen_left_count_ = last_left_count_;
  if (right && !frozen_right_) frozen_right_count_ = last_right_count_;
  frozen_left_ = left;
  frozen_right_ = right;
}

protocol::ControllerState EmulatedMotorController::state() const {
  if (brakingFaults() != 0) return protocol::ControllerState::kFault;
  return applied_brake_ ? protocol::ControllerState::kDisabled
                        : protocol::ControllerState::kEnabled;
}

void EmulatedMotorController::handleFrame(const CanFrame& frame, double now) {
  protocol::Message message;
  const protocol::DecodeError error = protocol::decode(frame, &message);
  if (error != protocol::DecodeError::kNone) {
    if (frame.id == protocol::kTorqueCommandId && !frame.error) {
      ++stats_.decode_errors;
      latched_faults_ |= protocol::kFaultBadCommand;
    }
    return;
  }
  if (const auto* command = std::get_if<protocol::TorqueCommand>(&message)) {
    // A drive command decided longer ago than the watchdog is stale: dropped, reported. A
    // braking one is never refused.
    const double age = protocol::timeTagAge(command->time_tag, now);
    if (command->enable && !command->brake &&
        (age > config_.command_timeout || age < -kFutureTolerance)) {
      ++stats_.commands_stale;
      latched_faults_ |= protocol::kFaultStaleCommand;
      return;
    }
    std::uint32_t lost = 0;
    if (command_sequence_.accept(command->sequence, &lost) != SequenceTracker::Verdict::kInOrder) {
      ++stats_.commands_out_of_order;
      return;
    }
    stats_.commands_lost += lost;
    ++stats_.commands;
    command_ = *command;
    has_command_ = true;
    last_command_time_ = now;
    if (command->brake || !command->enable) {
      // Re-arm: a braking command acknowledges the silence and bad-frame faults.
      latched_faults_ &= static_cast<std::uint16_t>(
          ~(protocol::kFaultCommandTimeout | protocol::kFaultDriverHeartbeatLost |
            protocol::kFaultBadCommand | protocol::kFaultStaleCommand));
    }
  } else if (std::holds_alternative<protocol::DriverHeartbeat>(message)) {
    has_driver_heartbeat_ = true;
    last_driver_heartbeat_ = now;
  }
}

void EmulatedMotorController::step(double now) {
  rx_.clear();
  transport_.receive(rx_);
  if (!powered_) {  // no supply: frames go unheard, the spring brakes hold the wheels
    applied_left_ = applied_right_ = 0.0;
    applied_brake_ = true;
    plant_.applyTorques(0.0, 0.0, true);
    return;
  }
  for (const CanFrame& frame : rx_) handleFrame(frame, now);

  const bool command_silent = !has_command_ || now - last_command_time_ >= config_.command_timeout;
  const bool driver_silent =
      !has_driver_heartbeat_ || now - last_driver_heartbeat_ >= config_.driver_timeout;
  const std::uint16_t before = latched_faults_;
  if (command_silent) latched_faults_ |= protocol::kFaultCommandTimeout;
  if (driver_silent) latched_faults_ |= protocol::kFaultDriverHeartbeatLost;
  if (latched_faults_ != before) {
    ++stats_.timeouts;
    command_sequence_.reset();
  }

  const bool drive = brakingFaults() == 0 && command_.enable && !command_.brake;
  const auto saturate = [this](double t) {
    return std::clamp(t, -config_.max_torque, config_.max_torque);
  };
  applied_left_ = drive ? saturate(command_.left) : 0.0;
  applied_right_ = drive ? saturate(command_.right) : 0.0;
  applied_brake_ = !drive;
  plant_.applyTorques(applied_left_, applied_right_, applied_brake_);

  if (now >= next_encoder_time_) {
    next_encoder_time_ = nextDeadline(next_encoder_time_, config_.encoder_period, now);
    const WheelAngles angles = plant_.wheelAngles();
    last_left_count_ = angleToCounts(angles.left, config_.counts_per_rev);
    last_right_count_ = angleToCounts(angles.right, config_.counts_per_rev);
    send(protocol::EncoderCounts{frozen_left_ ? frozen_left_count_ : last_left_count_,
                                 frozen_right_ ? frozen_right_count_ : last_right_count_,
                                 encoder_sequence_++});
    send(protocol::ControllerStatus{state(), faults(), status_sequence_++});
  }
  if (now >= next_heartbeat_time_) {
    next_heartbeat_time_ = nextDeadline(next_heartbeat_time_, config_.heartbeat_period, now);
    send(protocol::ControllerHeartbeat{state(), heartbeat_counter_++});
  }
}

void EmulatedMotorController::send(const protocol::Message& message) {
  if (silent_) return;
  if (transport_.send(protocol::encode(message))) ++stats_.frames_sent;
}

}  // namespace wheelchair_can
