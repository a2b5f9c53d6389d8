// A transport-neutral CAN frame (classic CAN 2.0, at most 8 data bytes) and receive filters.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace wheelchair_can {

struct CanFrame {
  std::uint32_t id = 0;  ///< 11-bit (or 29-bit if extended) identifier; error class if `error`
  std::uint8_t dlc = 0;  ///< number of valid data bytes, 0..8
  std::array<std::uint8_t, 8> data{};
  bool extended = false;  ///< 29-bit identifier (CAN 2.0B)
  bool remote = false;    ///< remote transmission request
  bool error = false;     ///< error frame (SocketCAN CAN_ERR_FLAG): id holds CAN_ERR_* classes
  double stamp = 0.0;     ///< receive (or send) time [s] on the transport's clock
};

/// Accepts a frame when (frame.id & mask) == (id & mask), as SocketCAN's struct can_filter.
/// Error frames always pass (they are reported, never filtered away).
struct CanFilter {
  std::uint32_t id = 0;
  std::uint32_t mask = 0;
};

/// True when `filters` is empty, the frame is an error frame, or one filter matches.
bool passesFilters(const CanFrame& frame, const std::vector<CanFilter>& filters);

}  // namespace wheelchair_can
