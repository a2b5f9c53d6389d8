// The base driver without ROS: the chair's own controller's commands and the safety
// supervisor's permits in, protocol frames out at a fixed rate; encoder/status/heartbeat frames
// in, odometry, a state and events out. Time is injected (`now` [s] on the bus clock; the wall
// clock separately where a frozen bus clock must not hide a silent motor controller).
//
// The chair moves only when everything holds: a motor controller alive and healthy, a fresh
// permit from the supervisor (sequence-numbered, renewed at its check rate), a fresh command
// from the controller (stamped and sequence-numbered), no e-stop and no latched stop.
//  - no command for command_timeout (100 ms)                   -> kCommandTimeout
//  - no MC heartbeat for controller_timeout (200 ms) / never   -> kControllerLost / kNoController
//  - MC reports a braking fault bit or the fault state          -> kControllerFault
//  - no permit for permit_timeout (100 ms): the supervisor was unloaded, crashed or hangs
//                                                                -> kNoPermit
//  - non-finite, out-of-range, stale, future or replayed commands -> rejected, counted, brake
//  - e-stop                                                      -> kEstop
// Latched until the rider's release (riderRelease, through the HMI), each with a sentence:
//  - e-stop; a torque command from a foreign publisher (onForeignCommand);
//  - any of the faults above beginning while driving (the drive is interrupted: after a hang or a
//    silence the chair never resumes on its own);
//  - a corrupted command stream (the MC reports bad command frames, or protocol frames that do
//    not decode arrive) while driving; a speed over max_speed; a wheel that does not count while
//    the other turns (a frozen encoder), a wheel that does not turn under torque or speeds up
//    against it (WheelMotionCheck); a motor controller silent in wall time while driving.
// A latch that leaves the command path intact (foreign command, corrupted stream, overspeed) and
// the supervisor's own stop (permit.stop) let the controller's controlled stop run for at most
// stop_window seconds, then brake; the others brake at once. The driver also limits torque (a
// larger one is rejected) and speed itself: torque that would speed the chair up beyond
// max_speed, or beyond the supervisor's speed limit (carried by its permit: no fresh permit, no
// limit to drive by, the brake) as heldSpeedLimit holds it + speed_limit_tolerance, is cut; a
// chair that does not slow down with that limit (2 x the tolerance above it) latches an
// overspeed too.
#pragma once

#include <wheelchair_base_driver/driver_config.h>
#include <wheelchair_base_driver/encoder_odometry.h>
#include <wheelchair_base_driver/wheel_motion_check.h>
#include <wheelchair_can/protocol.h>
#include <wheelchair_can/sequence_tracker.h>
#include <wheelchair_can/transport.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace wheelchair_base_driver {

enum class DriverState {
  kNoController = 0,   ///< no MC heartbeat seen yet
  kControllerLost,     ///< MC heartbeat silent for controller_timeout
  kControllerFault,    ///< MC reports faults
  kEstop,              ///< latched emergency stop
  kLatched,            ///< a latched stop (see above): braked until the rider's release
  kNoPermit,           ///< no fresh permit from the safety supervisor
  kWaitingForCommand,  ///< no fresh command (start, after a fault or a rejection)
  kCommandTimeout,     ///< commands stopped for command_timeout
  kSupervisorStop,     ///< the supervisor's stop, its controlled stop over: braked
  kStopping,           ///< a controlled stop in progress: the controller's commands pass
  kBraking,            ///< the command asks for the brake
  kDriving,            ///< torques are applied
};
const char* driverStateName(DriverState state);
/// True for the states that are faults (reported as errors to the stack).
bool isFault(DriverState state);
/// True for the states in which the controller's torques reach the motors.
bool isMoving(DriverState state);

enum class TorqueVerdict {
  kAccepted = 0,
  kNonFinite,
  kOutOfRange,
  kStale,
  kFuture,    ///< stamped ahead of the driver's clock
  kReplayed,  ///< a sequence number not above the last one of the same controller
  kUnstamped,
};
const char* torqueVerdictName(TorqueVerdict verdict);

/// Why a stop latched; each has a sentence for the rider.
enum class LatchCause {
  kNone = 0,
  kInterrupted,        ///< a fault began while driving (detail: which)
  kForeignCommand,     ///< a torque command from a publisher that is not the chair's controller
  kCorruptStream,      ///< bad command frames / undecodable protocol frames while driving
  kOverspeed,          ///< faster than max_speed, or than the supervisor's held speed limit
  kEncoderFault,       ///< a wheel does not count while the other turns under torque
  kWheelFault,         ///< a wheel does not turn under torque, or speeds up against it
  kControllerStalled,  ///< the MC silent for controller_wall_timeout of wall time while driving
};
const char* latchCauseName(LatchCause cause);

/// The chair's speed as the held limit starts from it: the measured |speed| at once when higher,
/// else falling no faster than `decel` [m/s^2] over `dt` [s] (a late encoder frame under load
/// reads low for one interval: the envelope does not follow it down):
/// envelope' = max(|speed|, envelope - decel dt).
double speedEnvelope(double envelope, double speed, double decel, double dt);

/// The supervisor's speed limit as the driver holds it while driving, advanced by `dt` [s]: a
/// rise of `limit` at once; a fall no faster than `decel` [m/s^2], from the last held value or,
/// if lower, the chair's speed envelope (or `ceiling`, the chair's max_speed):
/// held' = max(limit, min(held - decel dt, envelope, ceiling)).
double heldSpeedLimit(double held, double limit, double envelope, double ceiling, double decel,
                      double dt);

/// A command of the chair's own controller.
struct DriveInput {
  double left = 0.0, right = 0.0;  ///< [N m], positive forward
  bool brake = true;
  double stamp = 0.0;          ///< [s] when it was computed (required)
  std::uint64_t sequence = 0;  ///< strictly increasing within one session
  std::uint64_t session = 0;   ///< the controller's attachment (a new one restarts the sequence)
};

/// What the stack is told: on each change of (fault, latched, sentence).
struct DriverEvent {
  double stamp = 0.0;
  bool fault = false;
  bool latched = false;
  std::string sentence;  ///< for the rider ("" when all is well)
  std::string detail;    ///< for the log
};

struct DriverCounters {
  std::uint64_t torque_messages = 0;
  std::uint64_t rejected_non_finite = 0;
  std::uint64_t rejected_out_of_range = 0;
  std::uint64_t rejected_stale = 0;  ///< stale, future, replayed or unstamped
  std::uint64_t frames_sent = 0;
  std::uint64_t send_failures = 0;
  std::uint64_t frames_received = 0;
  std::uint64_t error_frames = 0;
  std::array<std::uint64_t, 8>
      decode_errors{};                   ///< indexed by wheelchair_can::protocol::DecodeError
  std::uint64_t foreign_commands = 0;    ///< torque/heartbeat frames of another driver on the bus
  std::uint64_t foreign_publishers = 0;  ///< torque messages of another node (onForeignCommand)
  std::uint64_t encoder_lost = 0;        ///< encoder frames skipped (sequence gaps)
  std::uint64_t encoder_duplicated = 0;
  std::uint64_t encoder_reordered = 0;
  std::uint64_t encoder_implausible = 0;
  std::uint64_t permits = 0;
  std::uint64_t permits_refused = 0;    ///< stale, replayed
  std::uint64_t command_timeouts = 0;   ///< transitions into kCommandTimeout
  std::uint64_t heartbeat_losses = 0;   ///< transitions into kControllerLost
  std::uint64_t controller_faults = 0;  ///< transitions into kControllerFault
  std::uint64_t permit_losses = 0;      ///< transitions into kNoPermit
  std::uint64_t latches = 0;
  std::uint64_t speed_limited = 0;  ///< frames whose torque was cut at the speed limit
  std::uint64_t estops = 0;
};

class BaseDriverCore {
 public:
  /// Throws std::invalid_argument if `config` is not valid (DriverConfig::validate).
  BaseDriverCore(const DriverConfig& config, wheelchair_can::CanTransport& transport);

  /// A command of the chair's own controller received at `now`; sends the resulting frame.
  TorqueVerdict onCommand(const DriveInput& command, double now);
  /// The supervisor's permit (DrivePermit): fresh for permit_timeout from `now` if its stamp is
  /// not older than that and its sequence is above the last one of the same session. It carries
  /// the supervisor's speed limit [m/s] (+inf: none; NaN or negative: 0).
  void onPermit(std::uint64_t sequence, std::uint64_t session, double stamp, bool stop, double now,
                double speed_limit = INFINITY);
  /// A torque command published by someone else (`who`): reported and braked on, latched.
  void onForeignCommand(const std::string& who, double now);
  void engageEstop(double now);
  /// The rider's own command to go on: clears the e-stop and a latched stop. Motion resumes
  /// only with a command received after it (and a fresh permit).
  void riderRelease(double now);
  /// Drains the transport, runs the watchdogs, sends due frames. Call at >= 100 Hz. `wall_now`
  /// (NaN: unknown) dates the MC's frames for checkWallLiveness.
  void spinOnce(double now, double wall_now = NAN);
  /// The MC silent for controller_wall_timeout of wall time while driving (the bus clock may
  /// stand still: a simulator that stopped) latches kControllerStalled and brakes.
  void checkWallLiveness(double now, double wall_now);
  /// The receive path for one frame (spinOnce calls it for every received frame).
  void processFrame(const wheelchair_can::CanFrame& frame, double now);
  /// The event since the last call, if the state as the stack sees it changed.
  std::optional<DriverEvent> takeEvent();

  DriverState state() const { return state_; }
  bool estopLatched() const { return estop_; }
  LatchCause latchCause() const { return latch_.cause; }
  /// The sentence for the rider of the current stop ("" when driving is allowed).
  std::string sentence() const;
  const DriverCounters& counters() const { return counters_; }
  const OdometryState& odometry() const { return odometry_.state(); }
  /// The last torque command put on the bus.
  const wheelchair_can::protocol::TorqueCommand& lastCommand() const { return last_sent_; }
  std::uint16_t controllerFaults() const { return mc_faults_; }
  wheelchair_can::protocol::ControllerState controllerState() const { return mc_state_; }
  const std::string& lastBusError() const { return last_bus_error_; }
  const std::string& lastRejection() const { return last_rejection_; }
  const std::string& latchDetail() const { return latch_.detail; }
  const DriverConfig& config() const { return config_; }
  /// [m/s] the supervisor's speed limit as the driver holds it now (+inf: none; not driving:
  /// the permit's limit itself, driving: heldSpeedLimit).
  double heldSpeedLimit() const { return held_limit_; }
  /// [m/s] faster than this, torque that speeds the chair up is cut (max_speed or the held limit).
  double speedCut() const;

 private:
  struct Latch {
    LatchCause cause = LatchCause::kNone;
    bool brake_now = true;  ///< false: the controller's controlled stop may run first
    double since = 0.0;
    std::string sentence, detail;
  };
  DriverState evaluate(double now) const;
  bool permitFresh(double now) const;
  void latch(LatchCause cause, bool brake_now, const std::string& sentence,
             const std::string& detail, double now);
  void update(double now, bool force_send);
  void holdSpeedLimit(double now);
  void checkMotion(double now);
  void sendCommand(double now);
  void sendHeartbeat();
  void handleEncoder(const wheelchair_can::protocol::EncoderCounts& counts, double stamp);
  void noteEvent(double now);

  DriverConfig config_;
  wheelchair_can::CanTransport& transport_;
  EncoderOdometry odometry_;
  std::vector<wheelchair_can::CanFrame> rx_;

  DriverState state_ = DriverState::kNoController;
  bool estop_ = false;
  Latch latch_;
  double block_time_ = -1e300;  ///< last time a blocking condition held
  double last_message_time_ = -1e300;
  bool has_message_ = false;
  bool message_brake_ = true;
  double message_left_ = 0.0, message_right_ = 0.0;
  double message_stamp_ = 0.0;
  std::uint64_t command_session_ = 0, command_sequence_in_ = 0;
  bool has_command_sequence_ = false;
  bool sticky_brake_ = false;  ///< a brake command during a stop: braked until it ends
  bool at_speed_limit_ = false;

  bool has_permit_ = false;
  double permit_time_ = -1e300;
  bool permit_stop_ = false;
  double permit_stop_since_ = 0.0;
  std::uint64_t permit_session_ = 0, permit_sequence_ = 0;
  double permit_limit_ = INFINITY;      ///< [m/s] the last fresh permit's speed limit
  double held_limit_ = INFINITY;        ///< [m/s] that limit as held (heldSpeedLimit)
  double held_limit_time_ = NAN;        ///< when held_limit_ was last advanced
  double speed_envelope_ = 0.0;         ///< [m/s] speedEnvelope of the measured speed
  double limit_overspeed_since_ = NAN;  ///< since when within the held limit + 2 tolerances

  bool has_heartbeat_ = false;
  double last_heartbeat_time_ = 0.0;
  double last_frame_wall_ = NAN;    ///< wall time of the last MC heartbeat
  double spin_wall_ = NAN;          ///< wall time of the spinOnce in progress
  double last_spin_time_ = -1e300;  ///< end of the last spinOnce [s]
  wheelchair_can::protocol::ControllerState mc_state_ =
      wheelchair_can::protocol::ControllerState::kInit;
  std::uint16_t mc_faults_ = 0;
  wheelchair_can::SequenceTracker encoder_sequence_;
  WheelMotionCheck wheel_check_;
  double overspeed_since_ = NAN;  ///< since when the speed is within max_speed

  wheelchair_can::protocol::TorqueCommand last_sent_;
  std::uint8_t command_sequence_ = 0;
  std::uint8_t heartbeat_counter_ = 0;
  double next_command_due_ = -1e300;    ///< next periodic torque frame [s]
  double next_heartbeat_due_ = -1e300;  ///< next driver heartbeat [s]
  DriverCounters counters_;
  std::string last_bus_error_;
  std::string last_rejection_;
  bool event_pending_ = false;
  bool report_after_release_ = false;  ///< the first state after a rider's release is reported
  DriverEvent event_, last_event_;
};

}  // namespace wheelchair_base_driver
