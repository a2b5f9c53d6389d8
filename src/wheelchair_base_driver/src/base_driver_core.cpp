#include <wheelchair_base_driver/base_driver_core.h>
#include <wheelchair_can/can_error.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_base_driver {

using wheelchair_can::CanFrame;
using wheelchair_can::SequenceTracker;
namespace protocol = wheelchair_can::protocol;
using protocol::ControllerState;

namespace {
constexpr double kScheduleSlack = 1e-3;  ///< [s] timer jitter tolerated by periodic frames

/// Periodic frames on a grid of `period`: due up to kScheduleSlack early, so a timer spinning
/// at the frame rate (ticks a little early or late) keeps the rate instead of skipping every
/// other period; a faster spin still sends exactly one frame per period. Restarts the grid at
/// `now` when forced (a frame sent at once) or after a stall of more than a period.
bool dueOnGrid(double now, double period, bool force, double& next_due) {
  if (!force && now < next_due - kScheduleSlack) return false;
  next_due = (force || now - next_due > period) ? now + period : next_due + period;
  return true;
}
}  // namespace

const char* driverStateName(DriverState s) {
  switch (s) {
    case DriverState::kNoController:
      return "no_motor_controller";
    case DriverState::kControllerLost:
      return "motor_controller_heartbeat_lost";
    case DriverState::kControllerFault:
      return "motor_controller_fault";
    case DriverState::kEstop:
      return "estop";
    case DriverState::kWaitingForCommand:
      return "waiting_for_command";
    case DriverState::kCommandTimeout:
      return "command_timeout";
    case DriverState::kBraking:
      return "braking";
    case DriverState::kDriving:
      return "driving";
  }
  return "?";
}

bool isFault(DriverState s) {
  return s == DriverState::kNoController || s == DriverState::kControllerLost ||
         s == DriverState::kControllerFault || s == DriverState::kEstop;
}

const char* torqueVerdictName(TorqueVerdict v) {
  switch (v) {
    case TorqueVerdict::kAccepted:
      return "accepted";
    case TorqueVerdict::kNonFinite:
      return "non-finite torque";
    case TorqueVerdict::kOutOfRange:
      return "torque beyond max_torque";
    case TorqueVerdict::kStale:
      return "stale message (header stamp older than command_timeout)";
  }
  return "?";
}

BaseDriverCore::BaseDriverCore(const DriverConfig& config, wheelchair_can::CanTransport& transport)
    : config_(config), transport_(transport), odometry_(config.geometry) {
  const std::string problem = config_.validate();
  if (!problem.empty()) throw std::invalid_argument("base driver: " + problem);
}

TorqueVerdict BaseDriverCore::onTorqueMessage(double left, double right, bool brake, double stamp,
                                              double now) {
  ++counters_.torque_messages;
  TorqueVerdict verdict = TorqueVerdict::kAccepted;
  if (!std::isfinite(left) || !std::isfinite(right)) {
    verdict = TorqueVerdict::kNonFinite;
    ++counters_.rejected_non_finite;
  } else if (std::abs(left) > config_.max_torque || std::abs(right) > config_.max_torque) {
    verdict = TorqueVerdict::kOutOfRange;
    ++counters_.rejected_out_of_range;
  } else if (stamp > 0 && now - stamp >= config_.command_timeout) {
    verdict = TorqueVerdict::kStale;
    ++counters_.rejected_stale;
  }
  if (verdict == TorqueVerdict::kAccepted) {
    has_message_ = true;
    last_message_time_ = now;
    message_left_ = left;
    message_right_ = right;
    message_brake_ = brake;
  } else {
    // A rejected message is a stop request: the previous command must not continue.
    last_rejection_ = torqueVerdictName(verdict);
    has_message_ = false;
    block_time_ = now;
  }
  update(now, true);
  return verdict;
}

void BaseDriverCore::engageEstop(double now) {
  if (!estop_) ++counters_.estops;
  estop_ = true;
  update(now, true);
}

void BaseDriverCore::clearEstop(double now) {
  estop_ = false;
  block_time_ = now;
  update(now, true);
}

void BaseDriverCore::spinOnce(double now) {
  rx_.clear();
  transport_.receive(rx_);
  for (const CanFrame& frame : rx_) processFrame(frame, now);
  update(now, false);
}

void BaseDriverCore::processFrame(const CanFrame& frame, double now) {
  if (frame.error) {
    ++counters_.error_frames;
    last_bus_error_ = wheelchair_can::decodeErrorFrame(frame).description;
    return;
  }
  ++counters_.frames_received;
  protocol::Message message;
  const protocol::DecodeError error = protocol::decode(frame, &message);
  if (error != protocol::DecodeError::kNone) {
    ++counters_.decode_errors[static_cast<std::size_t>(error)];
    return;
  }
  const double stamp = frame.stamp > 0 ? frame.stamp : now;
  if (const auto* counts = std::get_if<protocol::EncoderCounts>(&message)) {
    handleEncoder(*counts, stamp);
  } else if (const auto* status = std::get_if<protocol::ControllerStatus>(&message)) {
    mc_state_ = status->state;
    mc_faults_ = status->faults;
  } else if (const auto* heartbeat = std::get_if<protocol::ControllerHeartbeat>(&message)) {
    if (!has_heartbeat_ || now - last_heartbeat_time_ >= config_.controller_timeout) {
      encoder_sequence_.reset();  // after a silence the counter restarts anywhere
    }
    has_heartbeat_ = true;
    last_heartbeat_time_ = now;
    mc_state_ = heartbeat->state;
  } else {
    ++counters_.foreign_commands;  // our own message types, sent by someone else
  }
}

void BaseDriverCore::handleEncoder(const protocol::EncoderCounts& counts, double stamp) {
  std::uint32_t lost = 0;
  switch (encoder_sequence_.accept(counts.sequence, &lost)) {
    case SequenceTracker::Verdict::kDuplicate:
      ++counters_.encoder_duplicated;
      return;
    case SequenceTracker::Verdict::kReordered:
      ++counters_.encoder_reordered;
      return;
    case SequenceTracker::Verdict::kInOrder:
      counters_.encoder_lost += lost;
      break;
  }
  if (!odometry_.update(counts, stamp)) ++counters_.encoder_implausible;
}

DriverState BaseDriverCore::evaluate(double now) {
  if (estop_) return DriverState::kEstop;
  if (!has_heartbeat_) return DriverState::kNoController;
  if (now - last_heartbeat_time_ >= config_.controller_timeout) return DriverState::kControllerLost;
  if (mc_faults_ != 0 || mc_state_ == ControllerState::kFault) return DriverState::kControllerFault;
  if (!has_message_ || last_message_time_ <= block_time_) return DriverState::kWaitingForCommand;
  if (now - last_message_time_ >= config_.command_timeout) return DriverState::kCommandTimeout;
  return message_brake_ ? DriverState::kBraking : DriverState::kDriving;
}

void BaseDriverCore::update(double now, bool force_send) {
  const DriverState next = evaluate(now);
  if (isFault(next)) block_time_ = now;
  if (next != state_) {
    if (next == DriverState::kCommandTimeout) ++counters_.command_timeouts;
    if (next == DriverState::kControllerLost) ++counters_.heartbeat_losses;
    if (next == DriverState::kControllerFault) ++counters_.controller_faults;
    force_send = true;  // a change of state goes on the bus at once
  }
  state_ = next;
  if (dueOnGrid(now, config_.command_period, force_send, next_command_due_)) sendCommand();
  if (dueOnGrid(now, config_.heartbeat_period, false, next_heartbeat_due_)) sendHeartbeat();
}

void BaseDriverCore::sendCommand() {
  const bool drive = state_ == DriverState::kDriving;
  protocol::TorqueCommand command;
  command.left = drive ? message_left_ : 0.0;
  command.right = drive ? message_right_ : 0.0;
  command.enable = drive;
  command.brake = !drive;
  command.sequence = command_sequence_++;
  last_sent_ = command;
  if (transport_.send(protocol::encode(command))) {
    ++counters_.frames_sent;
  } else {
    ++counters_.send_failures;
  }
}

void BaseDriverCore::sendHeartbeat() {
  using protocol::DriverHeartbeatState;
  protocol::DriverHeartbeat heartbeat;
  heartbeat.state = state_ == DriverState::kDriving ? DriverHeartbeatState::kDriving
                    : state_ == DriverState::kEstop ? DriverHeartbeatState::kEstop
                    : isFault(state_)               ? DriverHeartbeatState::kFault
                                                    : DriverHeartbeatState::kBraking;
  heartbeat.counter = heartbeat_counter_++;
  if (transport_.send(protocol::encode(heartbeat))) {
    ++counters_.frames_sent;
  } else {
    ++counters_.send_failures;
  }
}

}  // namespace wheelchair_base_driver
