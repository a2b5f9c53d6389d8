#include <gtest/gtest.h>
#include <wheelchair_display/map_view.h>

#include <cmath>

namespace wheelchair_display {

TEST(MapView, NorthUpPutsTheMapsYAxisUpOnTheScreen) {
  ViewTransform v;
  v.scale = 10.0;
  v.screen_centre = {100, 100};
  const Eigen::Vector2d up = v.toScreen({0.0, 1.0});
  EXPECT_NEAR(up.x(), 100.0, 1e-9);
  EXPECT_NEAR(up.y(), 90.0, 1e-9);  // screen y grows downwards
  EXPECT_NEAR(v.toScreen({1.0, 0.0}).x(), 110.0, 1e-9);
}

TEST(MapView, ChairUpTurnsTheChairsHeadingUp) {
  const double yaw = 0.7;
  ViewTransform v;
  v.scale = 20.0;
  v.rotation = viewRotation(Orientation::kChairUp, yaw);
  v.world_centre = {3.0, 2.0};
  v.screen_centre = {500, 400};
  const Eigen::Vector2d ahead = v.toScreen({3.0 + std::cos(yaw), 2.0 + std::sin(yaw)});
  EXPECT_NEAR(ahead.x(), 500.0, 1e-9);
  EXPECT_NEAR(ahead.y(), 380.0, 1e-9);
  EXPECT_NEAR(v.screenHeading(yaw), M_PI / 2, 1e-12);
}

TEST(MapView, ScreenAndWorldAreInverse) {
  ViewTransform v;
  v.scale = 37.5;
  v.rotation = 1.1;
  v.world_centre = {-2.0, 5.0};
  v.screen_centre = {321, 123};
  const Eigen::Vector2d p(4.25, -1.5);
  EXPECT_LT((v.toWorld(v.toScreen(p)) - p).norm(), 1e-9);
}

TEST(MapView, FitShowsEveryPointInsideTheViewportWithItsMargin) {
  const Rect viewport{200, 100, 600, 400};
  const std::vector<Eigen::Vector2d> frame = {{0, 0}, {10, 12}, {3, 4}};
  for (double rotation : {0.0, 0.4, -2.0}) {
    const ViewTransform v = fitView(viewport, frame, rotation, 20.0, 1.0);
    for (const auto& p : frame) {
      const Eigen::Vector2d s = v.toScreen(p);
      EXPECT_GE(s.x(), 220 - 1e-6);
      EXPECT_LE(s.x(), 780 + 1e-6);
      EXPECT_GE(s.y(), 120 - 1e-6);
      EXPECT_LE(s.y(), 480 + 1e-6);
    }
  }
  // North-up: the 12 m side fills the 360 usable pixels.
  EXPECT_NEAR(fitView(viewport, frame, 0.0, 20.0, 1.0).scale, 30.0, 1e-9);
}

TEST(MapView, AChairAloneIsNotZoomedInBeyondTheMinimumExtent) {
  const ViewTransform v = fitView({0, 0, 400, 400}, {{1.0, 1.0}, {1.5, 1.2}}, 0.0, 0.0, 4.0);
  EXPECT_NEAR(v.scale, 100.0, 1e-9);
}

TEST(MapView, OrientationIsChosenByName) {
  EXPECT_EQ(orientationNamed("chair_up"), Orientation::kChairUp);
  EXPECT_EQ(orientationNamed("north_up"), Orientation::kNorthUp);
  EXPECT_THROW(orientationNamed("south_up"), std::invalid_argument);
}

}  // namespace wheelchair_display
