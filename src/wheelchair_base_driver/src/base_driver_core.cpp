#include <wheelchair_base_driver/base_driver_core.h>
#include <wheelchair_can/can_error.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace wheelchair_base_driver {

using wheelchair_can::CanFrame;
using wheelchair_can::SequenceTracker;
namespace protocol = wheelchair_can::protocol;
using protocol::ControllerState;

namespace {
constexpr double kScheduleSlack = 1e-3;    ///< [s] timer jitter tolerated by periodic frames
constexpr double kFutureTolerance = 0.01;  ///< [s] a stamp this far ahead is still "now"
constexpr double kEncoderFresh = 0.05;     ///< [s] encoder frames (100 Hz) newer than this flow
/// [s] over a speed limit this long latches: one encoder interval can show a spike when frames
/// come in a burst on a loaded PC (3.05 m/s seen in the one-switch system test at a true 0.7 m/s).
constexpr double kOverspeedTime = 0.1;
/// MC fault bits that are its watchdogs: it braked because commands came late or not at all.
constexpr std::uint16_t kWatchdogFaults = protocol::kFaultCommandTimeout |
                                          protocol::kFaultDriverHeartbeatLost |
                                          protocol::kFaultStaleCommand;

/// Periodic frames on a grid of `period`: due up to kScheduleSlack early, so a timer spinning
/// at the frame rate (ticks a little early or late) keeps the rate instead of skipping every
/// other period; a faster spin still sends exactly one frame per period. Restarts the grid at
/// `now` when forced (a frame sent at once) or after a stall of more than a period.
bool dueOnGrid(double now, double period, bool force, double& next_due) {
  if (!force && now < next_due - kScheduleSlack) return false;
  next_due = (force || now - next_due > period) ? now + period : next_due + period;
  return true;
}

bool isProtocolId(std::uint32_t id) {
  return id == protocol::kTorqueCommandId || id == protocol::kEncoderId ||
         id == protocol::kControllerStatusId || id == protocol::kDriverHeartbeatId ||
         id == protocol::kControllerHeartbeatId;
}

std::string format(const char* fmt, double value) {
  char text[160];
  std::snprintf(text, sizeof(text), fmt, value);
  return text;
}

/// The rider's words for the motor controller's fault bits.
const char* faultSentence(std::uint16_t faults) {
  if (faults != 0 && (faults & ~kWatchdogFaults) == 0) return "the motor commands came too late";
  return "the motors report a fault";
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
    case DriverState::kLatched:
      return "latched_stop";
    case DriverState::kNoPermit:
      return "no_safety_permit";
    case DriverState::kWaitingForCommand:
      return "waiting_for_command";
    case DriverState::kCommandTimeout:
      return "command_timeout";
    case DriverState::kSupervisorStop:
      return "safety_stop";
    case DriverState::kStopping:
      return "stopping";
    case DriverState::kBraking:
      return "braking";
    case DriverState::kDriving:
      return "driving";
  }
  return "?";
}

bool isFault(DriverState s) {
  return s == DriverState::kNoController || s == DriverState::kControllerLost ||
         s == DriverState::kControllerFault || s == DriverState::kEstop ||
         s == DriverState::kLatched || s == DriverState::kNoPermit;
}

bool isMoving(DriverState s) { return s == DriverState::kDriving || s == DriverState::kStopping; }

const char* torqueVerdictName(TorqueVerdict v) {
  switch (v) {
    case TorqueVerdict::kAccepted:
      return "accepted";
    case TorqueVerdict::kNonFinite:
      return "non-finite torque";
    case TorqueVerdict::kOutOfRange:
      return "torque beyond max_torque";
    case TorqueVerdict::kStale:
      return "stale command (stamp older than command_timeout)";
    case TorqueVerdict::kFuture:
      return "command stamped in the future";
    case TorqueVerdict::kReplayed:
      return "replayed command (sequence not increasing)";
    case TorqueVerdict::kUnstamped:
      return "command without a stamp";
  }
  return "?";
}

const char* latchCauseName(LatchCause c) {
  switch (c) {
    case LatchCause::kNone:
      return "none";
    case LatchCause::kInterrupted:
      return "drive interrupted";
    case LatchCause::kForeignCommand:
      return "foreign command";
    case LatchCause::kCorruptStream:
      return "corrupted command stream";
    case LatchCause::kOverspeed:
      return "overspeed";
    case LatchCause::kEncoderFault:
      return "encoder fault";
    case LatchCause::kWheelFault:
      return "wheel fault";
    case LatchCause::kControllerStalled:
      return "motor controller stalled";
  }
  return "?";
}

double speedEnvelope(double envelope, double speed, double decel, double dt) {
  return std::max(std::abs(speed), envelope - decel * dt);
}

double heldSpeedLimit(double held, double limit, double envelope, double ceiling, double decel,
                      double dt) {
  if (limit >= held) return limit;
  return std::max(limit, std::min({held - decel * dt, envelope, ceiling}));
}

BaseDriverCore::BaseDriverCore(const DriverConfig& config, wheelchair_can::CanTransport& transport)
    : config_(config), transport_(transport), odometry_(config.geometry), wheel_check_(config) {
  const std::string problem = config_.validate();
  if (!problem.empty()) throw std::invalid_argument("base driver: " + problem);
}

TorqueVerdict BaseDriverCore::onCommand(const DriveInput& c, double now) {
  ++counters_.torque_messages;
  TorqueVerdict verdict = TorqueVerdict::kAccepted;
  if (!std::isfinite(c.left) || !std::isfinite(c.right)) {
    verdict = TorqueVerdict::kNonFinite;
  } else if (std::abs(c.left) > config_.max_torque || std::abs(c.right) > config_.max_torque) {
    verdict = TorqueVerdict::kOutOfRange;
  } else if (!(c.stamp > 0) || !std::isfinite(c.stamp)) {
    verdict = TorqueVerdict::kUnstamped;
  } else if (now - c.stamp >= config_.command_timeout) {
    verdict = TorqueVerdict::kStale;
  } else if (c.stamp - now > kFutureTolerance) {
    verdict = TorqueVerdict::kFuture;
  } else if (has_command_sequence_ && c.session == command_session_ &&
             c.sequence <= command_sequence_in_) {
    verdict = TorqueVerdict::kReplayed;
  }
  if (verdict == TorqueVerdict::kAccepted) {
    has_message_ = true;
    last_message_time_ = now;
    message_left_ = c.left;
    message_right_ = c.right;
    message_brake_ = c.brake;
    message_stamp_ = c.stamp;
    has_command_sequence_ = true;
    command_session_ = c.session;
    command_sequence_in_ = c.sequence;
    // The controlled stop ends in the brake: from then on braked until the stop is released.
    if (c.brake && (latch_.cause != LatchCause::kNone || permit_stop_)) sticky_brake_ = true;
  } else {
    if (verdict == TorqueVerdict::kNonFinite) ++counters_.rejected_non_finite;
    if (verdict == TorqueVerdict::kOutOfRange) ++counters_.rejected_out_of_range;
    if (verdict >= TorqueVerdict::kStale) ++counters_.rejected_stale;
    // A rejected command is a stop request: the previous command must not continue.
    last_rejection_ = torqueVerdictName(verdict);
    has_message_ = false;
    block_time_ = now;
  }
  update(now, true);
  return verdict;
}

void BaseDriverCore::onPermit(std::uint64_t sequence, std::uint64_t session, double stamp,
                              bool stop, double now, double speed_limit) {
  const bool replayed = has_permit_ && session == permit_session_ && sequence <= permit_sequence_;
  if (replayed || !std::isfinite(stamp) || now - stamp >= config_.permit_timeout ||
      stamp - now > kFutureTolerance) {
    ++counters_.permits_refused;
    return;
  }
  ++counters_.permits;
  has_permit_ = true;
  permit_session_ = session;
  permit_sequence_ = sequence;
  permit_time_ = stamp;
  permit_limit_ = speed_limit >= 0.0 ? speed_limit : 0.0;  // NaN or negative: no motion
  if (stop && !permit_stop_) permit_stop_since_ = now;
  if (!stop && permit_stop_) {
    block_time_ = now;  // the stop lifted: motion only on a command decided after it
    if (latch_.cause == LatchCause::kNone) sticky_brake_ = false;
  }
  permit_stop_ = stop;
  update(now, false);
}

void BaseDriverCore::onForeignCommand(const std::string& who, double now) {
  ++counters_.foreign_publishers;
  latch(LatchCause::kForeignCommand, true, "another program tried to drive the chair",
        "wheel torques published by " + who, now);
  update(now, true);
}

void BaseDriverCore::engageEstop(double now) {
  if (!estop_) ++counters_.estops;
  estop_ = true;
  update(now, true);
}

void BaseDriverCore::riderRelease(double now) {
  estop_ = false;
  latch_ = Latch();
  sticky_brake_ = false;
  block_time_ = now;
  // The brake frame sent now re-arms the MC's bad-frame report; a new bad frame sets it again.
  mc_faults_ &= static_cast<std::uint16_t>(~protocol::kReportOnlyFaults);
  // The supervisor forgets the driver's fault at the release: a fault that still holds must be
  // reported again even where the release changed nothing the rider would hear.
  report_after_release_ = true;
  update(now, true);
}

void BaseDriverCore::latch(LatchCause cause, bool brake_now, const std::string& sentence,
                           const std::string& detail, double now) {
  if (latch_.cause != LatchCause::kNone) {
    latch_.brake_now = latch_.brake_now || brake_now;  // a worse fault brakes at once; keep why
    return;
  }
  ++counters_.latches;
  latch_ = Latch{cause, brake_now, now, sentence, detail};
}

bool BaseDriverCore::permitFresh(double now) const {
  return has_permit_ && now - permit_time_ < config_.permit_timeout;
}

void BaseDriverCore::spinOnce(double now, double wall_now) {
  rx_.clear();
  transport_.receive(rx_);
  spin_wall_ = wall_now;
  for (const CanFrame& frame : rx_) processFrame(frame, now);
  spin_wall_ = NAN;
  update(now, false);
  last_spin_time_ = now;
}

void BaseDriverCore::checkWallLiveness(double now, double wall_now) {
  if (!has_heartbeat_ || !std::isfinite(last_frame_wall_) || !isMoving(state_)) return;
  const double silent = wall_now - last_frame_wall_;
  if (silent <= config_.controller_wall_timeout) return;
  latch(LatchCause::kControllerStalled, true, "the motor controller stopped answering",
        format("no motor controller heartbeat for %.2f s of wall time while driving", silent), now);
  update(now, true);
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
    // Our identifiers that do not decode: the command stream cannot be trusted. Other devices'
    // identifiers are counted only.
    if (isProtocolId(frame.id) && !frame.extended && isMoving(state_)) {
      char id[16];
      std::snprintf(id, sizeof(id), "0x%03X", static_cast<unsigned>(frame.id));
      latch(LatchCause::kCorruptStream, false, "the motor commands were garbled",
            std::string("undecodable ") + id + " frame (" + protocol::decodeErrorName(error) + ")",
            now);
    }
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
    if (std::isfinite(spin_wall_)) last_frame_wall_ = spin_wall_;
    mc_state_ = heartbeat->state;
  } else {
    // Our own message types, sent by someone else: another driver commands the motors.
    ++counters_.foreign_commands;
    latch(LatchCause::kForeignCommand, true, "another device is sending motor commands",
          frame.id == protocol::kTorqueCommandId ? "a torque command frame of another sender"
                                                 : "a driver heartbeat of another sender",
          now);
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
  const OdometryState& o = odometry_.state();
  wheel_check_.onEncoder(stamp, o.left_angle, o.right_angle);
}

double BaseDriverCore::speedCut() const {
  return std::min(config_.max_speed, held_limit_ + config_.speed_limit_tolerance);
}

void BaseDriverCore::holdSpeedLimit(double now) {
  const double dt = std::isfinite(held_limit_time_) ? std::max(0.0, now - held_limit_time_) : 0.0;
  const double v = odometry_.state().v, decel = config_.speed_limit_decel;
  held_limit_time_ = now;
  if (!isMoving(state_)) {  // braked: nothing to slow down, the limit holds as it is
    speed_envelope_ = std::abs(v);
    held_limit_ = permit_limit_;
    return;
  }
  speed_envelope_ = speedEnvelope(speed_envelope_, v, decel, dt);
  held_limit_ = wheelchair_base_driver::heldSpeedLimit(held_limit_, permit_limit_, speed_envelope_,
                                                       config_.max_speed, decel, dt);
}

void BaseDriverCore::checkMotion(double now) {
  const OdometryState& o = odometry_.state();
  if (!isMoving(state_)) {
    // Not driving: a wheel standing still now says nothing about its encoder later.
    wheel_check_.reset(now, o.left_angle, o.right_angle);
    overspeed_since_ = limit_overspeed_since_ = now;
    return;
  }
  const double speed = std::abs(o.v);
  if (speed <= config_.max_speed) overspeed_since_ = now;
  if (now - overspeed_since_ >= kOverspeedTime)
    latch(LatchCause::kOverspeed, false, "the chair went faster than its limit",
          format("%.2f m/s measured by the encoders", speed) +
              format(", limit %.2f m/s", config_.max_speed),
          now);
  // The supervisor's limit: its torque cut leaves the chair to roll, so a chair still well above
  // the held limit did not slow down with it (its controller did not brake). Its own stop is
  // already a stop.
  if (permit_stop_ || speed <= held_limit_ + 2.0 * config_.speed_limit_tolerance)
    limit_overspeed_since_ = now;
  if (now - limit_overspeed_since_ >= kOverspeedTime)
    latch(LatchCause::kOverspeed, false, "the chair went faster than its safety limit",
          format("%.2f m/s measured by the encoders", speed) +
              format(", the safety supervisor's limit held at %.2f m/s", held_limit_),
          now);
  if ((mc_faults_ & protocol::kReportOnlyFaults) != 0)
    latch(LatchCause::kCorruptStream, false, "the motor commands were garbled",
          "the motor controller reports bad command frames", now);
  // Only while encoder frames arrive (a silent controller is another fault) and torque drives.
  const bool counting = now - o.stamp < kEncoderFresh && !message_brake_;
  const WheelVerdict wheels = wheel_check_.check(
      now, counting, {message_brake_ ? 0.0 : message_left_, o.left_angle, o.left_rate},
      {message_brake_ ? 0.0 : message_right_, o.right_angle, o.right_rate});
  switch (wheels.fault) {
    case WheelFault::kNone:
      break;
    case WheelFault::kFrozenEncoder:
      latch(LatchCause::kEncoderFault, true, "a wheel sensor failed", wheels.detail, now);
      break;
    case WheelFault::kStalled:
      latch(LatchCause::kWheelFault, true, "a wheel does not turn", wheels.detail, now);
      break;
    case WheelFault::kAgainstCommand:
      latch(LatchCause::kWheelFault, true, "a wheel turned the wrong way", wheels.detail, now);
      break;
  }
}

DriverState BaseDriverCore::evaluate(double now) const {
  if (estop_) return DriverState::kEstop;
  const bool latched = latch_.cause != LatchCause::kNone;
  // A controlled stop may run (the command path is intact) for stop_window, then the brake; a
  // brake command ends it at once.
  const auto stop_over = [&](double since) {
    return sticky_brake_ || now - since >= config_.stop_window;
  };
  if (latched && (latch_.brake_now || stop_over(latch_.since))) return DriverState::kLatched;
  if (!has_heartbeat_) return DriverState::kNoController;
  if (now - last_heartbeat_time_ >= config_.controller_timeout) return DriverState::kControllerLost;
  if ((mc_faults_ & ~protocol::kReportOnlyFaults) != 0 || mc_state_ == ControllerState::kFault)
    return DriverState::kControllerFault;
  if (!permitFresh(now)) return DriverState::kNoPermit;
  if (permit_stop_ && stop_over(permit_stop_since_)) return DriverState::kSupervisorStop;
  if (!has_message_ || last_message_time_ <= block_time_) return DriverState::kWaitingForCommand;
  if (now - last_message_time_ >= config_.command_timeout) return DriverState::kCommandTimeout;
  if (latched || permit_stop_) {
    if (message_brake_) return latched ? DriverState::kLatched : DriverState::kSupervisorStop;
    return DriverState::kStopping;
  }
  return message_brake_ ? DriverState::kBraking : DriverState::kDriving;
}

std::string BaseDriverCore::sentence() const {
  if (estop_) return "the emergency stop is engaged";
  if (latch_.cause != LatchCause::kNone) return latch_.sentence;
  switch (state_) {
    case DriverState::kNoController:
    case DriverState::kControllerLost:
      return "the motor controller is not answering";
    case DriverState::kControllerFault:
      return faultSentence(mc_faults_);
    case DriverState::kNoPermit:
      return "the safety supervisor is not running";
    default:
      return "";
  }
}

void BaseDriverCore::update(double now, bool force_send) {
  holdSpeedLimit(now);
  checkMotion(now);
  const DriverState raw = evaluate(now);
  DriverState next = raw;
  if (raw != state_) {
    // A fault or a silent controller while the torques reached the motors ends the drive: after
    // a hang, a silence or a fault the chair never resumes on its own.
    const bool interrupted = isMoving(state_) && !estop_ && latch_.cause == LatchCause::kNone &&
                             (isFault(raw) || raw == DriverState::kCommandTimeout);
    if (interrupted) {
      // The driver itself did not run (the chair process stood still): that is why.
      const bool paused = now - last_spin_time_ > config_.command_timeout;
      const std::string why =
          paused                                 ? "the chair's computer paused"
          : raw == DriverState::kCommandTimeout  ? "the chair's controller stopped sending commands"
          : raw == DriverState::kNoPermit        ? "the safety supervisor is not running"
          : raw == DriverState::kControllerFault ? faultSentence(mc_faults_)
                                                 : "the motor controller stopped answering";
      std::string detail = std::string(driverStateName(raw)) + " while driving";
      if (paused) detail += format(" (the driver did not run for %.2f s)", now - last_spin_time_);
      if (raw == DriverState::kControllerFault)
        detail += " (" + protocol::describeFaults(mc_faults_) + ")";
      latch(LatchCause::kInterrupted, true, why, detail, now);
      next = evaluate(now);
    }
    if (raw == DriverState::kCommandTimeout) ++counters_.command_timeouts;
    if (raw == DriverState::kControllerLost) ++counters_.heartbeat_losses;
    if (raw == DriverState::kControllerFault) ++counters_.controller_faults;
    if (raw == DriverState::kNoPermit && has_permit_) ++counters_.permit_losses;
  }
  if (next != state_) force_send = true;  // a change of state goes on the bus at once
  // Crossing the speed limit goes on the bus at once too (the torque that speeds up is cut).
  const bool at_limit = isMoving(next) && std::abs(odometry_.state().v) >= speedCut();
  if (at_limit != at_speed_limit_) force_send = true;
  at_speed_limit_ = at_limit;
  if (isFault(next)) block_time_ = now;
  state_ = next;
  if (dueOnGrid(now, config_.command_period, force_send, next_command_due_)) sendCommand(now);
  if (dueOnGrid(now, config_.heartbeat_period, false, next_heartbeat_due_)) sendHeartbeat();
  noteEvent(now);
}

void BaseDriverCore::sendCommand(double now) {
  const bool drive = isMoving(state_);
  protocol::TorqueCommand command;
  command.left = drive ? message_left_ : 0.0;
  command.right = drive ? message_right_ : 0.0;
  const double v = odometry_.state().v;
  if (drive && std::abs(v) >= speedCut()) {
    // At the speed limit (max_speed, or the supervisor's as held) no wheel may push it faster.
    const auto cut = [v](double t) { return v > 0 ? std::min(t, 0.0) : std::max(t, 0.0); };
    command.left = cut(command.left);
    command.right = cut(command.right);
    ++counters_.speed_limited;
  }
  command.enable = drive;
  command.brake = !drive;
  command.sequence = command_sequence_++;
  // A drive frame carries the time its command was decided (the MC refuses it when older than
  // its watchdog); a brake frame is decided now.
  command.time_tag = protocol::timeTag(drive ? message_stamp_ : now);
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
  heartbeat.state = isMoving(state_)                ? DriverHeartbeatState::kDriving
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

void BaseDriverCore::noteEvent(double now) {
  DriverEvent e;
  e.stamp = now;
  e.fault = isFault(state_);
  e.latched = estop_ || latch_.cause != LatchCause::kNone;
  e.sentence = sentence();
  if (!report_after_release_ && e.fault == last_event_.fault && e.latched == last_event_.latched &&
      e.sentence == last_event_.sentence)
    return;
  report_after_release_ = false;
  e.detail = std::string(driverStateName(state_));
  if (latch_.cause != LatchCause::kNone)
    e.detail += std::string(": ") + latchCauseName(latch_.cause) + ": " + latch_.detail;
  else if (state_ == DriverState::kControllerFault)
    e.detail += ": " + protocol::describeFaults(mc_faults_);
  last_event_ = e;
  event_ = e;
  event_pending_ = true;
}

std::optional<DriverEvent> BaseDriverCore::takeEvent() {
  if (!event_pending_) return std::nullopt;
  event_pending_ = false;
  return event_;
}

}  // namespace wheelchair_base_driver
