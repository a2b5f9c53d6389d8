// wheelchair_can's MotorPlant view of the simulator: left/right land on the right wheels.
#include <wheelchair_can/emulated_motor_controller.h>
#include <wheelchair_can/fake_bus.h>
#include <wheelchair_can/protocol.h>
#include <wheelchair_sim/motor_plant_adapter.h>
#include <wheelchair_sim/simulator.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

namespace wheelchair_sim {
namespace {

TEST(MotorPlantAdapter, LeftAndRightReachTheirWheels) {
  const auto chair = test::chair();
  SimParams params;
  Simulator direct(chair, params, nullptr), adapted(chair, params, nullptr);
  SimulatorMotorPlant plant(adapted);
  direct.applyWheelTorques(9.0, 2.0, false);  // right, left
  plant.applyTorques(2.0, 9.0, false);        // left, right
  direct.step(1.0);
  adapted.step(1.0);
  EXPECT_EQ(test::asVector(adapted.pose()), test::asVector(direct.pose()));
  EXPECT_GT(adapted.velocity().omega, 0.1);  // stronger right wheel turns the chair left
  const auto angles = plant.wheelAngles();
  EXPECT_EQ(angles.right, adapted.readWheels().angle(0));
  EXPECT_EQ(angles.left, adapted.readWheels().angle(1));
  EXPECT_GT(angles.right, angles.left);
}

TEST(MotorPlantAdapter, BrakeReachesTheSimulator) {
  const auto chair = test::chair();
  Simulator sim(chair, SimParams(), nullptr);
  SimulatorMotorPlant plant(sim);
  plant.applyTorques(10.0, 10.0, true);
  sim.step(1.0);
  EXPECT_EQ(test::asVector(sim.velocity()), Eigen::Vector2d::Zero());
}

// The simulator as the chair's motor controller on the fake bus, as the nodelet runs it with
// ~motor_bus fake: a driver's enabling torque command drives the chair forward, encoder frames
// come back, and silence brakes it.
TEST(MotorPlantAdapter, TheEmulatedControllerOnTheFakeBusDrivesTheSimulator) {
  namespace can = wheelchair_can;
  namespace protocol = wheelchair_can::protocol;
  const auto chair = test::chair();
  Simulator sim(chair, SimParams(), nullptr);
  SimulatorMotorPlant plant(sim);
  double now = 0.0;
  auto bus = can::FakeBus::create([&now] { return now; });
  auto driver = bus->connect("driver"), motor = bus->connect("simulator");
  can::EmulatedControllerConfig config;
  config.max_torque = chair.max_wheel_torque;
  can::EmulatedMotorController controller(config, *motor, plant);
  std::uint8_t sequence = 0;
  int encoder_frames = 0;
  const auto run = [&](double seconds, bool drive) {
    for (int i = 0; i < static_cast<int>(seconds / 0.005 + 0.5); ++i) {
      if (drive) {
        driver->send(protocol::encode(protocol::DriverHeartbeat{}));
        // Brake first (the controller starts latched), then enable.
        driver->send(protocol::encode(protocol::TorqueCommand{
            10.0, 10.0, sequence > 0, sequence == 0, sequence, protocol::timeTag(now)}));
        ++sequence;
      }
      controller.step(now);
      sim.step(0.005);
      now += 0.005;
      std::vector<can::CanFrame> rx;
      driver->receive(rx);
      for (const can::CanFrame& f : rx) encoder_frames += f.id == protocol::kEncoderId;
    }
  };
  run(1.0, true);
  EXPECT_GT(sim.pose().x, 0.05) << "enabled forward torques move the chair forward";
  EXPECT_GT(sim.velocity().v, 0.1);
  EXPECT_NEAR(encoder_frames, 100, 2) << "encoder frames at 100 Hz";
  run(1.0, false);  // no commands: the controller's 100 ms watchdog brakes
  EXPECT_NEAR(sim.velocity().v, 0.0, 1e-3);
  EXPECT_TRUE(controller.braking());
}

}  // namespace
}  // namespace wheelchair_sim
