// A cross-process stand-in for a CAN bus on one machine without vcan: every frame is one UDP
// datagram on 127.0.0.1 (16 bytes: "WC", flags, dlc, id LE32, 8 data bytes). Non-blocking.
// With remote_port == 0 the peer is learnt from the first datagram received.
#pragma once

#include <wheelchair_can/transport.h>

#include <array>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>

namespace wheelchair_can {

constexpr std::size_t kUdpFrameSize = 16;
std::array<std::uint8_t, kUdpFrameSize> packUdpFrame(const CanFrame& frame);
/// Unpacks a datagram; nullopt for a wrong size, magic or length code.
std::optional<CanFrame> unpackUdpFrame(const std::uint8_t* bytes, std::size_t size);

class UdpTransport : public CanTransport {
 public:
  using Clock = std::function<double()>;
  /// Binds 127.0.0.1:`local_port` (0 = any free port). Throws std::runtime_error on failure.
  UdpTransport(std::uint16_t local_port, std::uint16_t remote_port, Clock clock,
               std::vector<CanFilter> filters = {});
  ~UdpTransport() override;
  std::uint16_t localPort() const { return local_port_; }

  bool send(const CanFrame& frame) override;
  void receive(std::vector<CanFrame>& out) override;
  TransportStats stats() const override;
  std::string describe() const override;

 private:
  int fd_ = -1;
  std::uint16_t local_port_ = 0;
  Clock clock_;
  const std::vector<CanFilter> filters_;
  mutable std::mutex mutex_;
  std::uint16_t remote_port_ = 0;
  TransportStats stats_;
};

}  // namespace wheelchair_can
