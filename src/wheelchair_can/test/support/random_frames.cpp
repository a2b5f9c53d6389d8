#include <wheelchair_can/protocol.h>
#include <wheelchair_can_testing/random_frames.h>

namespace wheelchair_can::test {
namespace {

constexpr std::uint32_t kProtocolIds[] = {
    protocol::kTorqueCommandId, protocol::kEncoderId, protocol::kControllerStatusId,
    protocol::kDriverHeartbeatId, protocol::kControllerHeartbeatId};

}  // namespace

CanFrame randomFrame(std::mt19937_64& rng) {
  CanFrame f;
  const unsigned kind = rng() % 100;
  f.dlc = static_cast<std::uint8_t>(rng() % 9);
  for (auto& b : f.data) b = static_cast<std::uint8_t>(rng());
  if (kind < 5) {  // error frame with random classes and details
    f.error = true;
    f.id = static_cast<std::uint32_t>(rng()) & 0x1FFFFFFF;
    return f;
  }
  f.extended = kind < 10;
  f.remote = kind >= 10 && kind < 13;
  f.id = f.extended ? static_cast<std::uint32_t>(rng()) & 0x1FFFFFFF
                    : static_cast<std::uint32_t>(rng()) & 0x7FF;
  if (kind >= 50) f.id = kProtocolIds[rng() % 5];  // aim at the decoders
  if (kind >= 80 && f.dlc > 0) {
    // Valid CRC: only the content is random, so decoders accept some of these.
    f.data[f.dlc - 1] = protocol::frameCrc(f.id, f.data.data(), f.dlc - 1u);
  }
  return f;
}

}  // namespace wheelchair_can::test
