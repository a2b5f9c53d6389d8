// Footprint collisions against the ground-truth grid stop and hold the chair.
#include <wheelchair_sim/simulated_chair.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

namespace wheelchair_sim {
namespace {

SimParams quietParams() {
  SimParams p;
  p.laser_range_noise = 0.0;
  return p;
}

double frontOf(const wheelchair_description::ChairParams& c) {
  double front = -1e9;
  for (const auto& v : c.footprint) front = std::max(front, v.x());
  return front;
}

TEST(Collision, PushIntoAWallStopsAndHoldsTheChair) {
  const auto chair = test::chair();
  const double wall = 2.0;
  SimulatedChair sim(chair, quietParams(), test::wallWorld(wall));
  ASSERT_FALSE(sim.simulator().collided());
  sim.simulator().applyWheelTorques(20.0, 20.0, false);
  int collisions = 0;
  for (int i = 0; i < 500; ++i) collisions += sim.advance(0.01).collision_started;
  EXPECT_EQ(collisions, 1);
  ASSERT_TRUE(sim.simulator().collided());
  const Eigen::Vector3d held = test::asVector(sim.simulator().pose());
  // Stopped where its front touches the wall (within one cell), at rest.
  EXPECT_LT(held.x() + frontOf(chair), wall);
  EXPECT_GT(held.x() + frontOf(chair), wall - 0.05);
  EXPECT_EQ(test::asVector(sim.simulator().velocity()), Eigen::Vector2d::Zero());
  for (int i = 0; i < 100; ++i) sim.advance(0.01);
  EXPECT_EQ(test::asVector(sim.simulator().pose()), held);
}

TEST(Collision, NoFalseAlarmNearAWall) {
  const auto chair = test::chair();
  SimulatedChair sim(chair, quietParams(), test::wallWorld(2.0));
  ASSERT_TRUE(sim.teleport({2.0 - frontOf(chair) - 0.06, 0.0, 0.0}));
  sim.simulator().applyWheelTorques(3.0, -3.0, false);  // turning in place sweeps the corners
  sim.advance(0.3);
  EXPECT_FALSE(sim.simulator().collided());
}

TEST(Collision, TeleportIntoAWallIsRefusedAndAFreeTeleportClearsTheFlag) {
  const auto chair = test::chair();
  SimulatedChair sim(chair, quietParams(), test::wallWorld(2.0));
  EXPECT_FALSE(sim.teleport({2.0, 0.0, 0.0}));
  sim.simulator().applyWheelTorques(20.0, 20.0, false);
  for (int i = 0; i < 300; ++i) sim.advance(0.01);
  ASSERT_TRUE(sim.simulator().collided());
  ASSERT_TRUE(sim.teleport({0.0, 0.0, M_PI}));
  EXPECT_FALSE(sim.simulator().collided());
  sim.advance(0.5);  // still pushing: now away from the wall
  EXPECT_LT(sim.simulator().pose().x, -0.05);
}

TEST(Collision, AnObstacleUnderTheSeatIsDetected) {
  const auto chair = test::chair();
  auto world = test::wallWorld(8.0);
  world->setPos(-0.4, 0.0, 0.0f);  // one occupied cell well inside the footprint
  Simulator sim(chair, quietParams(), world);
  EXPECT_TRUE(sim.collides({0.0, 0.0, 0.0}));
  EXPECT_FALSE(sim.collides({3.0, 0.0, 0.0}));
}

TEST(Collision, LeavingTheMapIsACollision) {
  const auto chair = test::chair();
  Simulator sim(chair, quietParams(), test::wallWorld(8.0));
  EXPECT_TRUE(sim.collides({0.0, 4.9, 0.0}));
}

}  // namespace
}  // namespace wheelchair_sim
