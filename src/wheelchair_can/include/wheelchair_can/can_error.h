// Decoding of SocketCAN error frames (CAN_ERR_FLAG, linux/can/error.h) into a report.
#pragma once

#include <wheelchair_can/can_frame.h>
#include <wheelchair_can/transport.h>

#include <string>

namespace wheelchair_can {

struct CanErrorReport {
  bool bus_off = false;
  bool error_passive = false;   ///< controller reached error passive (RX or TX)
  bool error_warning = false;   ///< controller reached warning level (RX or TX)
  bool back_to_active = false;  ///< controller recovered to error active / restarted
  bool overflow = false;        ///< RX or TX buffer overflow: frames were lost
  std::string description;      ///< every reported class, e.g. "bus-off; no ACK"
};

/// Decodes an error frame's classes (frame.id) and details (data bytes). Non-error frames give
/// an empty report.
CanErrorReport decodeErrorFrame(const CanFrame& frame);

/// The bus state after `report`, starting from `current`.
BusState nextBusState(BusState current, const CanErrorReport& report);

}  // namespace wheelchair_can
