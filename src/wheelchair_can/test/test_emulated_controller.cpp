// The emulated motor controller, driven frame by frame from a hand-made driver endpoint.
#include <wheelchair_can/emulated_motor_controller.h>
#include <wheelchair_can/fake_bus.h>

#include <gtest/gtest.h>

#include <cmath>

namespace wheelchair_can {
namespace {

using protocol::TorqueCommand;

/// A plant whose wheel angles are set by the test.
struct ScriptedPlant : MotorPlant {
  void applyTorques(double l, double r, bool b) override {
    left = l;
    right = r;
    brake = b;
  }
  WheelAngles wheelAngles() const override { return angles; }
  std::uint16_t hardwareFaults() const override { return faults; }
  double left = 99, right = 99;
  bool brake = false;
  WheelAngles angles;
  std::uint16_t faults = 0;
};

struct ControllerTest : ::testing::Test {
  ControllerTest()
      : bus(FakeBus::create([this] { return now; })),
        driver(bus->connect("driver")),
        motor(bus->connect("motor")),
        controller(config(), *motor, plant) {}
  static EmulatedControllerConfig config() {
    EmulatedControllerConfig c;
    c.max_torque = 20.0;
    return c;
  }
  /// A command decided `age` seconds before now (tagged on the bus clock).
  void command(double l, double r, bool enable, bool brake, double age = 0.0) {
    driver->send(protocol::encode(
        TorqueCommand{l, r, enable, brake, sequence++, protocol::timeTag(now - age)}));
  }
  void heartbeat() { driver->send(protocol::encode(protocol::DriverHeartbeat{})); }
  void step(double dt = 0.001) {
    now += dt;
    controller.step(now);
  }
  /// Brings the controller out of its start-up timeout: heartbeat + brake command.
  void arm() {
    heartbeat();
    command(0, 0, false, true);
    step();
    ASSERT_EQ(controller.faults(), 0);
  }
  std::vector<protocol::Message> received() {
    std::vector<CanFrame> rx;
    driver->receive(rx);
    std::vector<protocol::Message> out;
    for (const CanFrame& f : rx) {
      protocol::Message m;
      EXPECT_EQ(protocol::decode(f, &m), protocol::DecodeError::kNone);
      out.push_back(m);
    }
    return out;
  }

  double now = 0.0;
  std::uint8_t sequence = 0;
  std::shared_ptr<FakeBus> bus;
  std::shared_ptr<FakeBusEndpoint> driver, motor;
  ScriptedPlant plant;
  EmulatedMotorController controller;
};

TEST_F(ControllerTest, StartsBrakedWithTheTimeoutFault) {
  step();
  EXPECT_TRUE(plant.brake);
  EXPECT_EQ(plant.left, 0.0);
  EXPECT_TRUE(controller.faults() & protocol::kFaultCommandTimeout);
  EXPECT_EQ(controller.state(), protocol::ControllerState::kFault);
}

TEST_F(ControllerTest, AppliesEnabledTorquesWithSignAndSaturation) {
  arm();
  command(12.5, -3.25, true, false);
  step();
  EXPECT_FALSE(plant.brake);
  EXPECT_DOUBLE_EQ(plant.left, 12.5);
  EXPECT_DOUBLE_EQ(plant.right, -3.25);
  command(35.0, -50.0, true, false);
  step();
  EXPECT_DOUBLE_EQ(plant.left, 20.0);
  EXPECT_DOUBLE_EQ(plant.right, -20.0);
  command(5.0, 5.0, true, true);  // brake wins
  step();
  EXPECT_TRUE(plant.brake);
  EXPECT_EQ(plant.left, 0.0);
  command(5.0, 5.0, false, false);  // not enabled
  step();
  EXPECT_TRUE(plant.brake);
}

TEST_F(ControllerTest, CommandSilenceBrakesAndLatchesUntilABrakeCommand) {
  arm();
  command(5, 5, true, false);
  step();
  double braked_after = -1;
  const double t0 = now;
  for (int i = 0; i < 300 && braked_after < 0; ++i) {
    if (i % 40 == 0) heartbeat();
    step();
    if (plant.brake) braked_after = now - t0;
  }
  EXPECT_NEAR(braked_after, 0.1, 0.0015);
  EXPECT_TRUE(controller.faults() & protocol::kFaultCommandTimeout);
  command(5, 5, true, false);  // torque alone does not re-arm
  step();
  EXPECT_TRUE(plant.brake);
  command(0, 0, true, true);
  step();
  command(5, 5, true, false);
  step();
  EXPECT_FALSE(plant.brake);
  EXPECT_EQ(controller.stats().timeouts, 1u);
}

TEST_F(ControllerTest, DriverHeartbeatLossFaults) {
  arm();
  for (int i = 0; i < 250; ++i) {
    if (i % 10 == 0) command(1, 1, true, false);
    step();
  }
  EXPECT_TRUE(controller.faults() & protocol::kFaultDriverHeartbeatLost);
  EXPECT_TRUE(plant.brake);
}

// A corrupted frame is dropped and reported, not braked on: braking on each bad frame made
// 1 s of random frames 17 brake/release cycles (a jolt each); the driver ends the drive with one
// controlled stop instead, on the valid frames that still arrive.
TEST_F(ControllerTest, BadCommandFrameIsReportedWithoutBraking) {
  arm();
  command(4, 4, true, false);
  step();
  CanFrame bad = protocol::encode(TorqueCommand{1, 1, true, false, sequence++});
  bad.data[7] ^= 1;
  driver->send(bad);
  step();
  EXPECT_TRUE(controller.faults() & protocol::kFaultBadCommand);
  EXPECT_EQ(controller.brakingFaults(), 0);
  EXPECT_NE(controller.state(), protocol::ControllerState::kFault);
  EXPECT_FALSE(plant.brake) << "the last valid command goes on";
  EXPECT_DOUBLE_EQ(plant.left, 4.0);
  EXPECT_EQ(controller.stats().decode_errors, 1u);
  command(3, 3, true, false);
  step();
  EXPECT_DOUBLE_EQ(plant.left, 3.0);
  EXPECT_TRUE(controller.faults() & protocol::kFaultBadCommand) << "reported until re-armed";
  command(0, 0, false, true);
  step();
  EXPECT_EQ(controller.faults(), 0);
}

// A drive command decided more than the watchdog period ago (queued while the bus or a process
// stood still) never moves the wheels; a braking one is always taken.
TEST_F(ControllerTest, StaleDriveCommandsAreIgnoredAndReported) {
  arm();
  command(6, 6, true, false, 0.05);
  step();
  EXPECT_DOUBLE_EQ(plant.left, 6.0) << "50 ms old: within the 100 ms watchdog";
  command(9, 9, true, false, 0.2);
  step();
  EXPECT_EQ(controller.stats().commands_stale, 1u);
  EXPECT_TRUE(controller.faults() & protocol::kFaultStaleCommand);
  EXPECT_TRUE(plant.brake) << "a stale command is a fault: brake";
  EXPECT_EQ(plant.left, 0.0);
  command(0, 0, false, true, 0.3);  // an old brake command still brakes and re-arms
  step();
  EXPECT_EQ(controller.faults(), 0);
  command(2, 2, true, false);
  step();
  EXPECT_DOUBLE_EQ(plant.left, 2.0);
}

TEST_F(ControllerTest, PowerRemovedHoldsTheBrakesSilentlyAndRestartsLatched) {
  arm();
  command(5, 5, true, false);
  step();
  ASSERT_FALSE(plant.brake);
  received();
  controller.setPowered(false);
  for (int i = 0; i < 100; ++i) {
    if (i % 10 == 0) command(5, 5, true, false);
    step();
  }
  EXPECT_TRUE(plant.brake);
  EXPECT_EQ(plant.left, 0.0);
  EXPECT_TRUE(received().empty()) << "an unpowered controller sends nothing";
  controller.setPowered(true);
  command(5, 5, true, false);
  step();
  EXPECT_TRUE(plant.brake) << "after power-up it waits for a brake command, as at start-up";
  EXPECT_TRUE(controller.faults() & protocol::kFaultCommandTimeout);
}

TEST_F(ControllerTest, AFrozenEncoderReportsTheCountItHad) {
  arm();
  plant.angles = {2 * M_PI, 2 * M_PI};
  step(0.011);
  controller.freezeEncoders(true, false);
  plant.angles = {4 * M_PI, 4 * M_PI};
  std::uint32_t left = 0, right = 0;
  for (int i = 0; i < 30; ++i) {
    step();
    for (const auto& m : received())
      if (auto* e = std::get_if<protocol::EncoderCounts>(&m)) left = e->left, right = e->right;
  }
  EXPECT_EQ(left, 4096u) << "frozen at one revolution";
  EXPECT_EQ(right, 8192u);
}

TEST_F(ControllerTest, SendsEncoderCountsStatusAndHeartbeatAtTheirRates) {
  arm();
  received();
  plant.angles = {2 * M_PI * 1.5, -2 * M_PI * 0.25};
  plant.faults = protocol::kFaultOvertemperature;
  int encoders = 0, statuses = 0, heartbeats = 0;
  std::uint8_t last_sequence = 0;
  for (int i = 0; i < 1000; ++i) {
    step();
    for (const auto& m : received()) {
      if (auto* e = std::get_if<protocol::EncoderCounts>(&m)) {
        EXPECT_EQ(e->left, 6144u);                // 1.5 rev * 4096
        EXPECT_EQ(e->right, (1u << 24) - 1024u);  // -0.25 rev, two's complement in 24 bits
        if (encoders > 0) {
          EXPECT_EQ(e->sequence, static_cast<std::uint8_t>(last_sequence + 1));
        }
        last_sequence = e->sequence;
        ++encoders;
      }
      if (auto* s = std::get_if<protocol::ControllerStatus>(&m)) {
        EXPECT_TRUE(s->faults & protocol::kFaultOvertemperature);
        EXPECT_EQ(s->state, protocol::ControllerState::kFault);
        ++statuses;
      }
      if (std::holds_alternative<protocol::ControllerHeartbeat>(m)) ++heartbeats;
    }
  }
  EXPECT_NEAR(encoders, 100, 1);
  EXPECT_NEAR(statuses, 100, 1);
  EXPECT_NEAR(heartbeats, 20, 1);
  EXPECT_TRUE(plant.brake);  // hardware fault: no torque
}

TEST_F(ControllerTest, LostAndReorderedCommandsAreCounted) {
  arm();
  sequence += 3;  // three commands never sent
  command(1, 1, true, false);
  step();
  EXPECT_EQ(controller.stats().commands_lost, 3u);
  sequence -= 2;  // an old one
  command(9, 9, true, false);
  step();
  EXPECT_EQ(controller.stats().commands_out_of_order, 1u);
  EXPECT_DOUBLE_EQ(plant.left, 1.0);
}

}  // namespace
}  // namespace wheelchair_can
