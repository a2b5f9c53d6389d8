// The live obstacle layer against the ground truth of scans simulated (MRPT) in the synthetic
// room with a person (a 0.5 m disc) the static map does not have: the person is seen within the
// two returns eq. (1) needs, free rays clear the cells once the person walked away (in the number
// of scans the clamp and eq. (1) give), a person who left the laser's view is forgotten within
// forget_time (and not before), and the static map's own walls, seen with pose noise, never
// become obstacles.
#include <gtest/gtest.h>
#include <wheelchair_mapping/obstacle_layer.h>

#include <cmath>

#include "synthetic_world.h"

namespace wheelchair_mapping {
namespace {

using wheelchair_core::OccupancyMap;
using wheelchair_core::Pose2D;

/// The room with a disc of `radius` at (x, y) occupied (the truth the laser sees).
OccupancyMap withPerson(OccupancyMap m, double x, double y, double radius = 0.25) {
  for (int iy = 0; iy < m.height; ++iy) {
    for (int ix = 0; ix < m.width; ++ix) {
      double cx, cy;
      m.cellToWorld(ix, iy, cx, cy);
      if (std::hypot(cx - x, cy - y) <= radius) m.at(ix, iy) = wheelchair_core::kOccupied;
    }
  }
  return m;
}

/// Obstacle cells of the layer within `d` of (x, y), and elsewhere.
void countObstacles(const ObstacleLayer& layer, const OccupancyMap& m, double x, double y, double d,
                    int& near, int& far) {
  near = far = 0;
  for (int iy = 0; iy < m.height; ++iy) {
    for (int ix = 0; ix < m.width; ++ix) {
      if (!layer.isObstacle(ix, iy)) continue;
      double cx, cy;
      m.cellToWorld(ix, iy, cx, cy);
      if (std::hypot(cx - x, cy - y) <= d) {
        ++near;
      } else {
        ++far;
      }
    }
  }
}

class ObstacleLayerTest : public ::testing::Test {
 protected:
  void SetUp() override { mrpt::random::getRandomGenerator().randomize(7); }
  const OccupancyMap room_ = test::syntheticRoom();
  const Pose2D sensor_{2.0, 2.0, 0.0};  // facing +x, the person 2 m ahead
  const double px_ = 4.0, py_ = 2.0;
  const mrpt::maps::COccupancyGridMap2D with_person_ = toMrptGrid(withPerson(room_, px_, py_));
  const mrpt::maps::COccupancyGridMap2D empty_ = toMrptGrid(room_);
  double stamp_ = 0.0;

  InsertResult scan(ObstacleLayer& layer, const mrpt::maps::COccupancyGridMap2D& truth,
                    const Pose2D& at, double dt = 0.1) {
    return layer.insert(test::simulateScan(truth, at, stamp_ += dt, 0.01), at);
  }
};

TEST_F(ObstacleLayerTest, APersonWhoAppearsIsSeenAfterTwoScansAndNothingElse) {
  ObstacleLayer layer(room_, ObstacleLayerConfig{});
  ASSERT_TRUE(scan(layer, with_person_, sensor_).inserted);
  int near = 0, far = 0;
  countObstacles(layer, room_, px_, py_, 0.35, near, far);
  EXPECT_EQ(near, 0) << "one return (P = 0.7) is below obstacle_probability 0.8";
  ASSERT_TRUE(scan(layer, with_person_, sensor_).inserted);
  countObstacles(layer, room_, px_, py_, 0.35, near, far);
  EXPECT_GE(near, 5);  // the lit half of a 0.5 m disc: ~10 cells
  EXPECT_EQ(far, 0);
  // Two returns 0.1 s apart: eq. (1) applied twice from the prior, the first one's log-odds
  // decayed in between by the rate that takes max_probability to obstacle_probability in
  // forget_time.
  int ix = -1, iy = -1;
  ASSERT_TRUE(room_.worldToCell(px_ - 0.25 + 0.01, py_, ix, iy));
  const ObstacleLayerConfig c;
  const auto logit = [](double p) { return std::log(p / (1 - p)); };
  const double rate =
      std::log(logit(c.max_probability) / logit(c.obstacle_probability)) / c.forget_time;
  const double first = logit(elfesUpdate(0.7, 0.5)) * std::exp(-rate * 0.1);
  const double expected = elfesUpdate(0.7, 1.0 / (1.0 + std::exp(-first)));
  if (!layer.isObstacle(ix, iy)) ++ix;  // the return may fall in the next cell
  EXPECT_NEAR(layer.probability(ix, iy), expected, 1e-6);
  EXPECT_EQ(layer.layer().at(ix, iy), wheelchair_core::kOccupied);
  // The cells between the laser and the person are free.
  ASSERT_TRUE(room_.worldToCell(3.0, 2.0, ix, iy));
  EXPECT_EQ(layer.layer().at(ix, iy), wheelchair_core::kFree);
}

TEST_F(ObstacleLayerTest, FreeRaysClearAPersonWhoWalkedAway) {
  const ObstacleLayerConfig config;
  ObstacleLayer layer(room_, config);
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(scan(layer, with_person_, sensor_).inserted);
  int near = 0, far = 0;
  countObstacles(layer, room_, px_, py_, 0.35, near, far);
  ASSERT_GE(near, 5);
  // Saturated at max_probability; each pass adds logit(p_occ_pass): the scans it takes to drop
  // below obstacle_probability (0.1 s apart, so the decay barely helps).
  const auto logit = [](double p) { return std::log(p / (1 - p)); };
  const int needed = static_cast<int>(
      std::ceil((logit(config.max_probability) - logit(config.obstacle_probability)) /
                -logit(config.model.p_occ_pass)));
  ASSERT_EQ(needed, 4);
  for (int k = 1; k <= needed; ++k) {
    ASSERT_TRUE(scan(layer, empty_, sensor_).inserted);
    countObstacles(layer, room_, px_, py_, 0.35, near, far);
    if (k == 1) {
      EXPECT_GT(near, 0) << "one free ray does not clear a saturated cell";
    }
  }
  EXPECT_EQ(near + far, 0) << "after " << needed << " scans through the place";
  EXPECT_EQ(layer.obstacleCount(), 0u);
}

TEST_F(ObstacleLayerTest, APersonOutOfViewIsForgottenWithinTheForgetTime) {
  const ObstacleLayerConfig config;
  ObstacleLayer layer(room_, config);
  for (int k = 0; k < 20; ++k) ASSERT_TRUE(scan(layer, with_person_, sensor_).inserted);
  ASSERT_GT(layer.obstacleCount(), 0u);
  // The chair turns away (facing -x): the person is behind the laser, never passed by a ray.
  const Pose2D away{sensor_.x, sensor_.y, M_PI};
  const double seen = stamp_;
  while (stamp_ < seen + config.forget_time - 0.15) {
    ASSERT_TRUE(scan(layer, with_person_, away).inserted);
    ASSERT_GT(layer.obstacleCount(), 0u) << "forgotten early, " << stamp_ - seen << " s";
  }
  layer.decayTo(seen + config.forget_time + 1e-6);
  EXPECT_EQ(layer.obstacleCount(), 0u);
}

TEST_F(ObstacleLayerTest, TheStaticMapsWallsSeenWithPoseNoiseAreNoObstacle) {
  ObstacleLayer layer(room_, ObstacleLayerConfig{});
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (const Pose2D& truth : test::loopTrajectory()) {
    const Pose2D believed{truth.x + noise(rng), truth.y + noise(rng), truth.yaw + noise(rng) / 4};
    ASSERT_TRUE(
        layer.insert(test::simulateScan(empty_, truth, stamp_ += 0.1, 0.01), believed).inserted);
  }
  EXPECT_EQ(layer.obstacleCount(), 0u);
}

TEST_F(ObstacleLayerTest, RefusesBadScansAndSettings) {
  ObstacleLayer layer(room_, ObstacleLayerConfig{});
  EXPECT_FALSE(scan(layer, empty_, Pose2D{NAN, 1.0, 0.0}).inserted);
  ASSERT_TRUE(scan(layer, empty_, sensor_).inserted);
  layer.decayTo(stamp_ + 0.5);  // the node decays to now between scans
  EXPECT_TRUE(scan(layer, empty_, sensor_, 0.05).inserted) << "a scan stamped before now";
  stamp_ -= 1.0;
  const InsertResult old = scan(layer, empty_, sensor_);
  EXPECT_FALSE(old.inserted);
  EXPECT_NE(old.reason.find("backwards"), std::string::npos) << old.reason;
  ObstacleLayerConfig bad;
  bad.obstacle_probability = 0.99;  // above max_probability: nothing could ever be an obstacle
  EXPECT_THROW(ObstacleLayer(room_, bad), std::invalid_argument);
  OccupancyMap rotated = room_;
  rotated.origin_yaw = 0.1;
  EXPECT_THROW(ObstacleLayer(rotated, ObstacleLayerConfig{}), std::invalid_argument);
}

}  // namespace
}  // namespace wheelchair_mapping
