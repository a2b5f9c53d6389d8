// Seeded random fuzzing of the driver's receive path: 10^6 random frames
// (wheelchair_can_testing's randomFrame) between genuine heartbeats and torque messages.
// Invariants: no crash, finite odometry, and every command the driver puts on the bus is
// either the last accepted torque message (cut to zero at the speed limit) or a brake. Random
// frames corrupt the stream and latch a stop; the rider releases it every 100 ms here.
#include "harness.h"

#include <wheelchair_can_testing/random_frames.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace wheelchair_base_driver {
namespace {

namespace protocol = wheelchair_can::protocol;
using test::CanFrame;
using wheelchair_can::test::randomFrame;

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
        ASSERT_TRUE(std::abs(c.left - left) < 0.005 || c.left == 0.0)
            << "frame " << i << ": sent " << c.left << ", " << c.right << " accepted " << left
            << ", " << right << " v " << h.driver.odometry().v << " state "
            << driverStateName(h.driver.state());
        ASSERT_TRUE(std::abs(c.right - right) < 0.005 || c.right == 0.0)
            << "frame " << i << ": sent " << c.left << ", " << c.right << " accepted " << left
            << ", " << right << " v " << h.driver.odometry().v << " state "
            << driverStateName(h.driver.state());
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
      if (i % 1000 == 0) h.driver.riderRelease(h.now);
      const bool bad = rng() % 10 == 0;
      const double l = bad ? std::nan("") : torque(rng), r = torque(rng);
      if (h.driver.onCommand({l, r, false, h.now, ++h.command_sequence, 1}, h.now) ==
          TorqueVerdict::kAccepted) {
        left = l;
        right = r;
        has_accepted = true;
      } else {
        has_accepted = false;  // a rejected message must stop the old command
      }
      h.permit();  // after the command: a frame it sends carries the command just checked
    }
    h.driver.processFrame(randomFrame(rng), h.now);
    ++frames;
    if (i % 10 == 0) {
      h.driver.spinOnce(h.now);
      check(i);
      // The state is re-evaluated by spinOnce: right after it, a reported fault means braking.
      if ((h.driver.controllerFaults() & ~protocol::kReportOnlyFaults) != 0) {
        ASSERT_NE(h.driver.state(), DriverState::kDriving);
        ASSERT_TRUE(h.driver.lastCommand().brake);
      }
    }
    ASSERT_TRUE(std::isfinite(h.driver.odometry().pose.x) &&
                std::isfinite(h.driver.odometry().pose.yaw));
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
