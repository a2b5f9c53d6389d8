// The transport interface every CAN back end implements (SocketCAN, in-process fake bus, UDP).
#pragma once

#include <wheelchair_can/can_frame.h>

#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_can {

/// ISO 11898 fault confinement states, plus "closed" (no socket / not connected).
enum class BusState { kClosed = 0, kActive, kWarning, kErrorPassive, kBusOff };
const char* busStateName(BusState state);

struct TransportStats {
  BusState state = BusState::kClosed;
  std::uint64_t tx_frames = 0;     ///< frames handed to the bus
  std::uint64_t tx_failed = 0;     ///< send() calls that could not queue the frame
  std::uint64_t rx_frames = 0;     ///< data frames delivered by receive()
  std::uint64_t rx_dropped = 0;    ///< frames lost in a full receive queue
  std::uint64_t error_frames = 0;  ///< error frames (CAN_ERR_FLAG) received
  std::uint64_t reopens = 0;       ///< times the link was (re)opened after a failure
  std::string last_error;          ///< human-readable description of the latest problem
};

class CanTransport {
 public:
  virtual ~CanTransport() = default;
  /// Queues one frame for transmission without blocking. False when it could not be queued.
  virtual bool send(const CanFrame& frame) = 0;
  /// Appends every frame received since the last call (data and error frames), never blocks.
  virtual void receive(std::vector<CanFrame>& out) = 0;
  virtual TransportStats stats() const = 0;
  virtual std::string describe() const = 0;
};

}  // namespace wheelchair_can
