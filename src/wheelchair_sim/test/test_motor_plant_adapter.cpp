// The base driver's MotorPlant view of the simulator: left/right land on the right wheels.
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
  EXPECT_EQ(adapted.pose(), direct.pose());
  EXPECT_GT(adapted.velocity()(1), 0.1);  // stronger right wheel turns the chair left
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
  EXPECT_EQ(sim.velocity(), Eigen::Vector2d::Zero());
}

}  // namespace
}  // namespace wheelchair_sim
