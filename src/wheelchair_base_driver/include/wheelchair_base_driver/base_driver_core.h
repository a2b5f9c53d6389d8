// The base driver without ROS: torque messages in, protocol frames out at a fixed rate,
// encoder/status/heartbeat frames in, odometry and a status out. Time is injected (`now` [s]).
//
// Safety rules (every one ends in zero torque with the brake command):
//  - no valid torque message for command_timeout (100 ms)    -> kCommandTimeout
//  - no MC heartbeat for controller_timeout (200 ms) / never -> kControllerLost / kNoController
//  - MC reports a fault bit or the fault state               -> kControllerFault
//  - non-finite, out-of-range or stale torques                -> rejected, counted, brake
//  - e-stop                                                   -> kEstop, latched until cleared
// After any of these, motion resumes only with a torque message received after the condition
// ended (no stale command can restart the chair).
#pragma once

#include <wheelchair_base_driver/driver_config.h>
#include <wheelchair_base_driver/encoder_odometry.h>
#include <wheelchair_can/protocol.h>
#include <wheelchair_can/sequence_tracker.h>
#include <wheelchair_can/transport.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_base_driver {

enum class DriverState {
  kNoController = 0,   ///< no MC heartbeat seen yet
  kControllerLost,     ///< MC heartbeat silent for controller_timeout
  kControllerFault,    ///< MC reports faults
  kEstop,              ///< latched emergency stop
  kWaitingForCommand,  ///< no fresh torque message (start, after a fault or a rejection)
  kCommandTimeout,     ///< torque messages stopped for command_timeout
  kBraking,            ///< the torque message asks for the brake
  kDriving,            ///< torques are applied
};
const char* driverStateName(DriverState state);
/// True for the states that are faults (reported as errors to the stack).
bool isFault(DriverState state);

enum class TorqueVerdict { kAccepted = 0, kNonFinite, kOutOfRange, kStale };
const char* torqueVerdictName(TorqueVerdict verdict);

struct DriverCounters {
  std::uint64_t torque_messages = 0;
  std::uint64_t rejected_non_finite = 0;
  std::uint64_t rejected_out_of_range = 0;
  std::uint64_t rejected_stale = 0;
  std::uint64_t frames_sent = 0;
  std::uint64_t send_failures = 0;
  std::uint64_t frames_received = 0;
  std::uint64_t error_frames = 0;
  std::array<std::uint64_t, 8>
      decode_errors{};                 ///< indexed by wheelchair_can::protocol::DecodeError
  std::uint64_t foreign_commands = 0;  ///< torque/heartbeat frames of another driver on the bus
  std::uint64_t encoder_lost = 0;      ///< encoder frames skipped (sequence gaps)
  std::uint64_t encoder_duplicated = 0;
  std::uint64_t encoder_reordered = 0;
  std::uint64_t encoder_implausible = 0;
  std::uint64_t command_timeouts = 0;   ///< transitions into kCommandTimeout
  std::uint64_t heartbeat_losses = 0;   ///< transitions into kControllerLost
  std::uint64_t controller_faults = 0;  ///< transitions into kControllerFault
  std::uint64_t estops = 0;
};

class BaseDriverCore {
 public:
  /// Throws std::invalid_argument if `config` is not valid (DriverConfig::validate).
  BaseDriverCore(const DriverConfig& config, wheelchair_can::CanTransport& transport);

  /// A wheelchair_msgs/WheelTorques message received at `now`; `stamp` is its header time
  /// (<= 0: unknown, not checked). Sends the resulting frame immediately.
  TorqueVerdict onTorqueMessage(double left, double right, bool brake, double stamp, double now);
  void engageEstop(double now);
  void clearEstop(double now);
  /// Drains the transport, runs the watchdogs, sends due frames. Call at >= 200 Hz.
  void spinOnce(double now);
  /// The receive path for one frame (spinOnce calls it for every received frame).
  void processFrame(const wheelchair_can::CanFrame& frame, double now);

  DriverState state() const { return state_; }
  bool estopLatched() const { return estop_; }
  const DriverCounters& counters() const { return counters_; }
  const OdometryState& odometry() const { return odometry_.state(); }
  /// The last torque command put on the bus.
  const wheelchair_can::protocol::TorqueCommand& lastCommand() const { return last_sent_; }
  std::uint16_t controllerFaults() const { return mc_faults_; }
  wheelchair_can::protocol::ControllerState controllerState() const { return mc_state_; }
  const std::string& lastBusError() const { return last_bus_error_; }
  const std::string& lastRejection() const { return last_rejection_; }
  const DriverConfig& config() const { return config_; }

 private:
  DriverState evaluate(double now);
  void update(double now, bool force_send);
  void sendCommand();
  void sendHeartbeat();
  void handleEncoder(const wheelchair_can::protocol::EncoderCounts& counts, double stamp);

  DriverConfig config_;
  wheelchair_can::CanTransport& transport_;
  EncoderOdometry odometry_;
  std::vector<wheelchair_can::CanFrame> rx_;

  DriverState state_ = DriverState::kNoController;
  bool estop_ = false;
  double block_time_ = -1e300;  ///< last time a blocking condition held
  double last_message_time_ = -1e300;
  bool has_message_ = false;
  bool message_brake_ = true;
  double message_left_ = 0.0, message_right_ = 0.0;

  bool has_heartbeat_ = false;
  double last_heartbeat_time_ = 0.0;
  wheelchair_can::protocol::ControllerState mc_state_ =
      wheelchair_can::protocol::ControllerState::kInit;
  std::uint16_t mc_faults_ = 0;
  wheelchair_can::SequenceTracker encoder_sequence_;

  wheelchair_can::protocol::TorqueCommand last_sent_;
  std::uint8_t command_sequence_ = 0;
  std::uint8_t heartbeat_counter_ = 0;
  double next_command_due_ = -1e300;    ///< next periodic torque frame [s]
  double next_heartbeat_due_ = -1e300;  ///< next driver heartbeat [s]
  DriverCounters counters_;
  std::string last_bus_error_;
  std::string last_rejection_;
};

}  // namespace wheelchair_base_driver
