// Route geometry against hand-computed values: distance to go, the stretch ahead, how close
// another route comes to it, and the obstacle layer's cells on the route ahead.
#include <wheelchair_navigator/route.h>

#include "test_world.h"

#include <gtest/gtest.h>

namespace wheelchair_navigator {
namespace {

using wheelchair_navigator_test::straight;
using wheelchair_navigator_test::testRoom;

/// An L: 4 m along x, then 2 m along y.
Route lRoute() {
  std::vector<Pose2D> poses = straight(1.0, 1.0, 5.0, 1.0);
  const auto up = straight(5.0, 1.0, 5.0, 3.0);
  poses.insert(poses.end(), up.begin() + 1, up.end());
  return Route(poses);
}

TEST(Route, DistanceToGoIsAlongTheRouteFromTheNearestVertex) {
  Route r = lRoute();
  EXPECT_NEAR(r.length(), 6.0, 1e-9);
  EXPECT_NEAR(r.advance({1.0, 1.0, 0.0}), 6.0, 1e-9);
  EXPECT_NEAR(r.advance({3.0, 1.1, 0.0}), 4.0 + 0.1, 1e-9);  // 0.1 m beside the route
  EXPECT_NEAR(r.cursorAlong(), 2.0, 1e-9);
  EXPECT_NEAR(r.advance({4.5, 1.0, 0.0}), 0.5 + 2.0, 1e-9);
  EXPECT_NEAR(r.advance({5.0, 2.5, 0.0}), 0.5, 1e-9);
}

TEST(Route, TheCursorOnlyMovesForwardWithinItsWindow) {
  // A route that comes back along itself: the chair at the start point on the way back is at
  // the return leg, not at the start.
  std::vector<Pose2D> poses = straight(1.0, 1.0, 2.0, 1.0);
  const auto back = straight(2.0, 1.0, 1.0, 1.0);
  poses.insert(poses.end(), back.begin() + 1, back.end());
  Route r(poses);
  r.advance({1.5, 1.0, 0.0});
  r.advance({2.0, 1.0, 0.0});
  EXPECT_NEAR(r.advance({1.5, 1.0, M_PI}), 0.5, 1e-9);
}

TEST(Route, TheStretchAheadAndPointsAlongIt) {
  Route r = lRoute();
  r.advance({3.0, 1.0, 0.0});
  const auto s = r.stretch(r.cursorAlong() + 0.5, r.cursorAlong() + 3.0);
  ASSERT_GE(s.size(), 2u);
  EXPECT_NEAR(s.front().x(), 3.5, 1e-9);
  EXPECT_NEAR(s.back().x(), 5.0, 1e-9);  // 2 m along x, then 1 m up the L
  EXPECT_NEAR(s.back().y(), 2.0, 1e-9);
  EXPECT_NEAR(r.pointAt(100.0).y(), 3.0, 1e-9) << "clamped to the end";
}

TEST(Route, HowCloseAnotherRouteComesToAStretch) {
  const std::vector<Eigen::Vector2d> stretch{{3.0, 1.0}, {4.0, 1.0}};
  EXPECT_NEAR(distanceToStretch(straight(3.5, 2.0, 3.5, 3.0), stretch, 10.0), 1.0, 1e-9);
  EXPECT_NEAR(distanceToStretch(straight(1.0, 1.0, 5.0, 1.0), stretch, 10.0), 0.0, 1e-9);
  // Only the first metre of the route is looked at: it reaches the stretch later.
  EXPECT_NEAR(distanceToStretch(straight(1.0, 1.0, 5.0, 1.0), stretch, 1.0), 1.0, 0.05);
  EXPECT_TRUE(std::isinf(distanceToStretch({}, stretch, 10.0)));
}

TEST(Route, TheLayerShowsOnlyObstaclesTheMapDoesNotHaveOnTheRouteAhead) {
  const auto map = testRoom();
  auto layer = map;
  Route r(straight(1.0, 2.5, 6.0, 2.5));
  EXPECT_FALSE(layerObstacleAhead(r, layer, map, 3.0, 0.35)) << "the map's own walls";
  int ix, iy;
  ASSERT_TRUE(layer.worldToCell(3.0, 2.8, ix, iy));  // 0.3 m beside the route, 2 m ahead
  layer.at(ix, iy) = wheelchair_core::kOccupied;
  const auto hit = layerObstacleAhead(r, layer, map, 3.0, 0.35);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->x(), 3.0, 0.05);
  EXPECT_FALSE(layerObstacleAhead(r, layer, map, 3.0, 0.2)) << "outside a narrower corridor";
  EXPECT_FALSE(layerObstacleAhead(r, layer, map, 1.5, 0.35)) << "beyond the lookahead";
  r.advance({4.0, 2.5, 0.0});
  EXPECT_FALSE(layerObstacleAhead(r, layer, map, 3.0, 0.35)) << "behind the chair";
}

}  // namespace
}  // namespace wheelchair_navigator
