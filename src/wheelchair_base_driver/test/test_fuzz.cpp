// Seeded random fuzzing: >= 10^6 random frames (random identifiers, lengths 0-8, payloads,
// extended/remote/error frames, and frames with a valid CRC on protocol identifiers) through
// the decoder and the driver's receive path. Invariants: no crash, finite odometry, and every
// command the driver puts on the bus is either the last accepted torque message or a brake.
#include "harness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace wheelchair_base_driver {
namespace {

constexpr std::uint32_t kProtocolIds[] = {
    protocol::kTorqueCommandId, protocol::kEncoderId, protocol::kControllerStatusId,
    protocol::kDriverHeartbeatId, protocol::kControllerHeartbeatId};

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

TEST(Fuzz, DecoderSurvivesAMillionRandomFramesAndOnlyAcceptsWellFormedOnes) {
  std::mt19937_64 rng(20261124);
  std::uint64_t accepted = 0;
  for (int i = 0; i < 1000000; ++i) {
    const CanFrame f = randomFrame(rng);
    protocol::Message m;
    const protocol::DecodeError e = protocol::decode(f, &m);
    if (e != protocol::DecodeError::kNone) continue;
    ++accepted;
    // Whatever was accepted re-encodes to the same bytes: no field was misread.
    const CanFrame again = protocol::encode(m);
    ASSERT_EQ(again.id, f.id);
    ASSERT_EQ(again.dlc, f.dlc);
    for (int b = 0; b < f.dlc; ++b) ASSERT_EQ(again.data[b], f.data[b]) << "id " << f.id;
  }
  EXPECT_GT(accepted, 1000u);  // the valid-CRC share reaches the message decoders
}

TEST(Fuzz, DriverReceivePathNeverSendsAWrongCommand) {
  test::Harness h;
  h.controller.setSilent(true);  // the test plays the controller: heartbeats + random frames
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> torque(-40.0, 40.0);
  double left = 0, right = 0;
  bool has_accepted = false;
  std::uint8_t counter = 0;
  std::uint64_t drove = 0, frames = 0;
  std::vector<CanFrame> sent;
  const auto check = [&](int i) {
    sent.clear();
    h.monitor->receive(sent);
    for (const CanFrame& f : sent) {
      protocol::Message m;
      if (f.id != protocol::kTorqueCommandId ||
          protocol::decode(f, &m) != protocol::DecodeError::kNone) {
        continue;
      }
      const auto& c = std::get<protocol::TorqueCommand>(m);
      if (c.enable && !c.brake) {
        ++drove;
        ASSERT_TRUE(has_accepted);
        ASSERT_NEAR(c.left, left, 0.005) << "frame " << i;
        ASSERT_NEAR(c.right, right, 0.005) << "frame " << i;
      } else {
        ASSERT_EQ(c.left, 0.0);
        ASSERT_EQ(c.right, 0.0);
      }
    }
  };
  for (int i = 0; i < 1000000; ++i) {
    h.now += 0.0001;
    if (i % 100 == 0) {  // every 10 ms: a genuine heartbeat, healthy status and a torque message
      h.monitor->send(protocol::encode(
          protocol::ControllerHeartbeat{protocol::ControllerState::kEnabled, counter}));
      h.monitor->send(protocol::encode(
          protocol::ControllerStatus{protocol::ControllerState::kEnabled, 0, counter++}));
      const bool bad = rng() % 10 == 0;
      const double l = bad ? std::nan("") : torque(rng), r = torque(rng);
      if (h.driver.onTorqueMessage(l, r, false, 0, h.now) == TorqueVerdict::kAccepted) {
        left = l;
        right = r;
        has_accepted = true;
      } else {
        has_accepted = false;  // a rejected message must stop the old command
      }
    }
    h.driver.processFrame(randomFrame(rng), h.now);
    ++frames;
    if (i % 10 == 0) {
      h.driver.spinOnce(h.now);
      check(i);
      // The state is re-evaluated by spinOnce: right after it, a reported fault means braking.
      if (h.driver.controllerFaults() != 0) {
        ASSERT_NE(h.driver.state(), DriverState::kDriving);
        ASSERT_TRUE(h.driver.lastCommand().brake);
      }
    }
    ASSERT_TRUE(std::isfinite(h.driver.odometry().x) && std::isfinite(h.driver.odometry().theta));
  }
  check(-1);
  EXPECT_EQ(frames, 1000000u);
  EXPECT_GT(drove, 1000u);  // the driver did drive between the random faults
  const DriverCounters& n = h.driver.counters();
  EXPECT_GT(n.error_frames, 0u);
  EXPECT_GT(n.decode_errors[static_cast<int>(protocol::DecodeError::kBadCrc)], 0u);
  EXPECT_GT(n.decode_errors[static_cast<int>(protocol::DecodeError::kUnknownId)], 0u);
}

}  // namespace
}  // namespace wheelchair_base_driver
