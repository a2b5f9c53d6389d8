// Obstacles that are not in the map (a person): seen by the laser where geometry says, and
// the chair collides with them, only from their appear time on.
#include <wheelchair_sim/simulated_chair.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wheelchair_sim {
namespace {

TEST(Obstacles, RayHitsTheNearSideOfADisc) {
  const std::vector<Disc> discs{{Eigen::Vector2d(3.0, 0.0), 0.5, 0.0}};
  EXPECT_NEAR(rayToDiscs({0.0, 0.0}, 0.0, discs), 2.5, 1e-12);
  // Tangent-ish ray at angle a: hits where the line's distance to the centre < r.
  const double a = std::asin(0.4 / 3.0);
  const double along = 3.0 * std::cos(a), half_chord = std::sqrt(0.25 - 0.16);
  EXPECT_NEAR(rayToDiscs({0.0, 0.0}, a, discs), along - half_chord, 1e-9);
  EXPECT_TRUE(std::isinf(rayToDiscs({0.0, 0.0}, M_PI, discs)));                  // behind
  EXPECT_TRUE(std::isinf(rayToDiscs({0.0, 0.0}, std::asin(0.6 / 3.0), discs)));  // passes by
  EXPECT_EQ(rayToDiscs({3.1, 0.0}, 1.0, discs), 0.0);                            // from inside
}

TEST(Obstacles, BadDiscsAreRefused) {
  ObstacleDiscs obstacles;
  EXPECT_THROW(obstacles.add({Eigen::Vector2d(NAN, 0.0), 0.15, 0.0}), std::invalid_argument);
  EXPECT_THROW(obstacles.add({Eigen::Vector2d(1.0, 0.0), 0.0, 0.0}), std::invalid_argument);
  EXPECT_TRUE(obstacles.all().empty());
}

TEST(Obstacles, LaserSeesAPersonOnlyOnceThere) {
  const auto chair = test::chair();
  SimParams params;
  params.laser_range_noise = 0.0;
  SimulatedChair sim(chair, params, test::wallWorld(6.0));
  const double person_x = 3.0, radius = 0.15;
  sim.simulator().obstacles().add({Eigen::Vector2d(person_x, 0.0), radius, 0.5});
  const int centre_beam = params.laser_beams / 2;
  const double expected = person_x - radius - chair.laser_x;  // the laser looks along +x
  double before = NAN, after = NAN;
  for (int i = 0; i < 100; ++i) {
    const SensorOutputs out = sim.advance(0.01);
    if (!out.scan) continue;
    (sim.simulator().time() < 0.5 ? before : after) = out.scan->ranges[centre_beam];
  }
  EXPECT_NEAR(before, 6.0 - chair.laser_x, 0.06);  // the wall
  EXPECT_NEAR(after, expected, 1e-3);
}

TEST(Obstacles, AWalkingPersonIsWhereItsVelocityTookItUntilItVanishes) {
  ObstacleDiscs obstacles;
  Disc walker;
  walker.centre = {1.0, 2.0};
  walker.appear_time = 10.0;
  walker.velocity = {0.5, -0.25};
  walker.vanish_time = 14.0;
  obstacles.add(walker);
  EXPECT_TRUE(obstacles.presentAt(9.99).empty());
  const auto at12 = obstacles.presentAt(12.0);
  ASSERT_EQ(at12.size(), 1u);
  EXPECT_NEAR(at12[0].centre.x(), 2.0, 1e-12);
  EXPECT_NEAR(at12[0].centre.y(), 1.5, 1e-12);
  EXPECT_TRUE(obstacles.presentAt(14.0).empty());
  walker.vanish_time = 10.0;
  EXPECT_THROW(obstacles.add(walker), std::invalid_argument);
  walker.vanish_time = INFINITY;
  walker.velocity = {NAN, 0.0};
  EXPECT_THROW(obstacles.add(walker), std::invalid_argument);
}

TEST(Obstacles, TheLaserSeesAWalkingPersonWhereItIsNow) {
  const auto chair = test::chair();
  SimParams params;
  params.laser_range_noise = 0.0;
  SimulatedChair sim(chair, params, test::wallWorld(8.0));
  Disc walker;
  walker.centre = {2.0, 0.0};
  walker.velocity = {1.0, 0.0};  // walking away along the beam at 1 m/s
  sim.simulator().obstacles().add(walker);
  const int centre_beam = params.laser_beams / 2;
  double last = NAN, when = NAN;
  for (int i = 0; i < 100; ++i) {
    const SensorOutputs out = sim.advance(0.01);
    if (out.scan) last = out.scan->ranges[centre_beam], when = sim.simulator().time();
  }
  ASSERT_FALSE(std::isnan(last));
  EXPECT_NEAR(last, 2.0 + when - walker.radius - chair.laser_x, 0.011);
}

TEST(Obstacles, DrivingIntoAPersonIsACollisionAndTeleportOntoOneIsRefused) {
  const auto chair = test::chair();
  SimParams params;
  SimulatedChair sim(chair, params, test::wallWorld(8.0));
  sim.simulator().obstacles().add({Eigen::Vector2d(2.5, 0.0), 0.15, 0.0});
  EXPECT_FALSE(sim.teleport({2.5, 0.0, 0.0}));
  sim.simulator().applyWheelTorques(20.0, 20.0, false);
  for (int i = 0; i < 400 && !sim.simulator().collided(); ++i) sim.advance(0.01);
  ASSERT_TRUE(sim.simulator().collided());
  double front = -1e9;
  for (const auto& v : chair.footprint) front = std::max(front, v.x());
  EXPECT_NEAR(sim.simulator().pose().x + front, 2.5 - 0.15, 0.03);
  sim.simulator().obstacles().clear();
  EXPECT_TRUE(sim.teleport({2.5, 0.0, 0.0}));
}

}  // namespace
}  // namespace wheelchair_sim
