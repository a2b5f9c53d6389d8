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
  void command(double l, double r, bool enable, bool brake) {
    driver->send(protocol::encode(TorqueCommand{l, r, enable, brake, sequence++}));
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

TEST_F(ControllerTest, BadCommandFrameFaults) {
  arm();
  CanFrame bad = protocol::encode(TorqueCommand{1, 1, true, false, sequence++});
  bad.data[7] ^= 1;
  driver->send(bad);
  step();
  EXPECT_TRUE(controller.faults() & protocol::kFaultBadCommand);
  EXPECT_TRUE(plant.brake);
  EXPECT_EQ(controller.stats().decode_errors, 1u);
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
