// Where the obstacle layer cuts the way, in the test room: a row of obstacles across the room
// cuts it (at the row), one obstacle the chair can pass does not, nor obstacles the map already
// has, nor anything when the map itself has no way there; an obstacle beside the chair cuts it
// where the chair is.
#include <wheelchair_navigator/goal_check.h>
#include <wheelchair_navigator/layer_cut.h>

#include "test_world.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wheelchair_navigator {
namespace {

using wheelchair_core::OccupancyMap;
using wheelchair_core::Pose2D;
using wheelchair_navigator_test::chairFootprint;
using wheelchair_navigator_test::kHalfWidth;
using wheelchair_navigator_test::testRoom;

const Pose2D kStart{1.5, 2.5, 0.0};
const Pose2D kGoal{8.5, 2.5, 0.0};
constexpr double kRadius = 0.35;

/// The layer on the test room's grid with no evidence anywhere.
OccupancyMap emptyLayer() {
  OccupancyMap layer = testRoom();
  layer.data.assign(layer.data.size(), wheelchair_core::kUnknown);
  return layer;
}

/// Marks every cell of `layer` whose centre lies within `r` of (x, y) as an obstacle.
void disc(OccupancyMap& layer, double x, double y, double r) {
  for (int iy = 0; iy < layer.height; ++iy) {
    for (int ix = 0; ix < layer.width; ++ix) {
      double cx, cy;
      layer.cellToWorld(ix, iy, cx, cy);
      if (std::hypot(cx - x, cy - y) <= r) layer.at(ix, iy) = wheelchair_core::kOccupied;
    }
  }
}

class LayerCutTest : public ::testing::Test {
 protected:
  std::optional<Eigen::Vector2d> cut(const OccupancyMap& layer, Pose2D start = kStart,
                                     Pose2D goal = kGoal) const {
    return layerCut(check.configSpace(), map, layer, start, goal, kRadius);
  }
  OccupancyMap map = testRoom();
  GoalCheck check{map, chairFootprint(), kHalfWidth};
};

TEST_F(LayerCutTest, NothingInTheLayerCutsNothing) { EXPECT_FALSE(cut(emptyLayer())); }

TEST_F(LayerCutTest, ARowOfObstaclesAcrossTheRoomCutsTheWayAtTheRow) {
  OccupancyMap layer = emptyLayer();
  for (double y = 0.1; y <= 5.0; y += 0.25) disc(layer, 5.0, y, 0.15);
  const auto at = cut(layer);
  ASSERT_TRUE(at);
  EXPECT_NEAR(at->x(), 5.0 - 0.15 - kRadius, 0.1);  // the first blocked cell before the row
  EXPECT_GT(at->y(), 0.1);
  EXPECT_LT(at->y(), 5.0);
}

TEST_F(LayerCutTest, OneObstacleTheChairCanPassDoesNotCutTheWay) {
  OccupancyMap layer = emptyLayer();
  disc(layer, 5.0, 2.5, 0.3);  // a person in the middle of a 4.9 m wide room
  EXPECT_FALSE(cut(layer));
}

TEST_F(LayerCutTest, ObstaclesTheMapAlreadyHasAreNotTheLayers) {
  OccupancyMap layer = emptyLayer();
  for (int iy = 0; iy < layer.height; ++iy)  // the walls and the block, seen by the laser
    for (int ix = 0; ix < layer.width; ++ix)
      if (map.at(ix, iy) == wheelchair_core::kOccupied) layer.at(ix, iy) = map.at(ix, iy);
  EXPECT_FALSE(cut(layer));
}

TEST_F(LayerCutTest, WithoutAWayOnTheMapItselfTheLayerIsNotTheCause) {
  OccupancyMap layer = emptyLayer();
  for (double y = 0.1; y <= 5.0; y += 0.25) disc(layer, 5.0, y, 0.15);
  EXPECT_FALSE(cut(layer, kStart, Pose2D{2.2, 5.6, 0.0}))
      << "a goal in the pocket, narrower than the chair, has no way on the map";
}

TEST_F(LayerCutTest, AnObstacleBesideTheChairCutsTheWayWhereTheChairIs) {
  OccupancyMap layer = emptyLayer();
  disc(layer, kStart.x + 0.3, kStart.y, 0.1);
  const auto at = cut(layer);
  ASSERT_TRUE(at);
  EXPECT_NEAR(at->x(), kStart.x, 1e-9);
  EXPECT_NEAR(at->y(), kStart.y, 1e-9);
}

TEST_F(LayerCutTest, ALayerOnAnotherGridIsNotRead) {
  OccupancyMap layer = emptyLayer();
  for (double y = 0.1; y <= 5.0; y += 0.25) disc(layer, 5.0, y, 0.15);
  layer.width -= 1;
  layer.data.resize(static_cast<size_t>(layer.width) * layer.height);
  EXPECT_FALSE(cut(layer));
}

}  // namespace
}  // namespace wheelchair_navigator
