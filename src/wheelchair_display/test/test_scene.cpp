#include <gtest/gtest.h>
#include <wheelchair_display/scene.h>

namespace wheelchair_display {
namespace {

std::vector<wheelchair_hmi::Place> threeRooms() {
  return {{"sofa", "living_room", {1, 1, 0}}, {"tv", "living_room", {3, 2, 0}},
          {"sink", "kitchen", {7, 1, 0}},     {"stove", "kitchen", {8, 2, 0}},
          {"bed", "bedroom", {2, 9, 0}},      {"lamp", "living_room", {1.5, 2.5, 0}}};
}

}  // namespace

TEST(Scene, RoomsAreTheAreasAroundTheirPlacesInFileOrder) {
  const auto rooms = roomAreas(threeRooms(), 0.5);
  ASSERT_EQ(rooms.size(), 3u);
  EXPECT_EQ(rooms[0].name, "living_room");
  EXPECT_EQ(rooms[0].places, (std::vector<size_t>{0, 1, 5}));
  EXPECT_NEAR(rooms[0].box.min.x(), 0.5, 1e-12);
  EXPECT_NEAR(rooms[0].box.max.y(), 3.0, 1e-12);
  EXPECT_EQ(roomAt(rooms, {7.5, 1.5}), 1);
  EXPECT_EQ(roomAt(rooms, {5.0, 5.0}), -1);
  EXPECT_EQ(roomNamed(rooms, "bedroom"), 2);
}

TEST(Scene, ThePointerPicksTheSmallerOfTwoOverlappingRooms) {
  const std::vector<wheelchair_hmi::Place> places = {
      {"a", "hall", {0, 0, 0}}, {"b", "hall", {10, 10, 0}}, {"c", "closet", {5, 5, 0}}};
  EXPECT_EQ(roomAt(roomAreas(places, 0.5), {5.2, 5.1}), 1);
}

TEST(Scene, KnownBoundsSkipUnknownCells) {
  wheelchair_core::OccupancyMap map;
  map.resolution = 0.5;
  map.origin_x = -1.0;
  map.origin_y = 2.0;
  map.width = 6;
  map.height = 4;
  map.data.assign(24, wheelchair_core::kUnknown);
  map.at(1, 1) = wheelchair_core::kFree;
  map.at(3, 2) = wheelchair_core::kOccupied;
  const auto box = knownBounds(map);
  EXPECT_NEAR(box.min.x(), -0.5, 1e-12);
  EXPECT_NEAR(box.min.y(), 2.5, 1e-12);
  EXPECT_NEAR(box.max.x(), 1.0, 1e-12);
  EXPECT_NEAR(box.max.y(), 3.5, 1e-12);
  map.data.assign(24, wheelchair_core::kUnknown);
  EXPECT_TRUE(knownBounds(map).empty());
}

TEST(Scene, LabelsDoNotCoverEachOtherWhenThereIsRoom) {
  const Rect bounds{0, 0, 800, 600};
  const std::vector<Eigen::Vector2d> anchors = {{300, 300}, {305, 300}, {300, 305}};
  const std::vector<std::pair<int, int>> sizes(3, {120, 30});
  const auto labels = placeLabels(anchors, sizes, bounds, 10);
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_FALSE(labels[i].covers) << i;
    for (size_t j = 0; j < i; ++j) EXPECT_FALSE(labels[i].rect.intersects(labels[j].rect));
    EXPECT_GE(labels[i].rect.x, 0);
    EXPECT_LE(labels[i].rect.right(), 800);
  }
}

TEST(Scene, ALabelWithNoFreeSpotSaysItCoversAnother) {
  const std::vector<Eigen::Vector2d> anchors = {{300, 300}, {305, 300}, {300, 305}, {310, 310}};
  const auto labels =
      placeLabels(anchors, std::vector<std::pair<int, int>>(4, {120, 30}), {0, 0, 800, 600}, 10);
  EXPECT_FALSE(labels[2].covers);
  EXPECT_TRUE(labels[3].covers);
}

TEST(Scene, LabelsKeepClearOfTheChair) {
  const Rect chair{300, 280, 60, 40};
  const auto labels = placeLabels({{300, 300}}, {{120, 30}}, {0, 0, 800, 600}, 10, {chair});
  EXPECT_FALSE(labels[0].covers);
  EXPECT_FALSE(labels[0].rect.intersects(chair));
}

TEST(Scene, ALabelAtTheEdgeStaysInside) {
  const auto labels = placeLabels({{790, 5}}, {{120, 30}}, {0, 0, 800, 600}, 10);
  EXPECT_LE(labels[0].rect.right(), 800);
  EXPECT_GE(labels[0].rect.y, 0);
}

TEST(Scene, TheViewFramesTheDriveTheRoomOrTheWholeMap) {
  wheelchair_core::Box overview;
  overview.min = {0, 0};
  overview.max = {10, 12};
  const wheelchair_core::Polygon chair = {{1, 1}, {2, 1}, {2, 2}};
  const std::vector<wheelchair_core::Pose2D> route = {{1.5, 1.5, 0}, {5, 5, 0}};
  const wheelchair_core::Pose2D goal{6, 5, 0};
  EXPECT_EQ(viewFrame(overview, &chair, route, &goal, nullptr).size(), 6u);
  const auto rooms = roomAreas(threeRooms(), 0.5);
  const auto room = viewFrame(overview, &chair, {}, nullptr, &rooms[1]);
  ASSERT_EQ(room.size(), 2u);
  EXPECT_NEAR(room[0].x(), 6.5, 1e-12);
  const auto whole = viewFrame(overview, &chair, {}, nullptr, nullptr);
  EXPECT_EQ(whole[1], Eigen::Vector2d(10, 12));
}

}  // namespace wheelchair_display
