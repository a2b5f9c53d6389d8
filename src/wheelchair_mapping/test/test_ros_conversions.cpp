#include <gtest/gtest.h>
#include <wheelchair_mapping/ros_conversions.h>

namespace wheelchair_mapping {
namespace {

TEST(RosConversions, RoundTripKeepsEverything) {
  OccupancyMap map;
  map.resolution = 0.1;
  map.origin_x = 1.25;
  map.origin_y = -4.5;
  map.origin_yaw = 0.3;
  map.width = 3;
  map.height = 2;
  map.data = {0, 100, -1, 50, 0, 0};
  const auto msg = toOccupancyGrid(map, "map", ros::Time(12.5));
  EXPECT_EQ(msg.header.frame_id, "map");
  EXPECT_EQ(msg.info.width, 3u);
  EXPECT_EQ(msg.info.height, 2u);
  EXPECT_NEAR(msg.info.origin.orientation.z, std::sin(0.15), 1e-12);
  EXPECT_EQ(msg.data[1], 100);  // row-major, row 0 at the bottom in both
  const OccupancyMap back = fromOccupancyGrid(msg);
  EXPECT_NEAR(back.resolution, 0.1, 1e-7);
  EXPECT_EQ(back.origin_x, 1.25);
  EXPECT_EQ(back.origin_y, -4.5);
  EXPECT_NEAR(back.origin_yaw, 0.3, 1e-12);
  EXPECT_EQ(back.data, map.data);
}

TEST(RosConversions, RejectsInconsistentMessages) {
  nav_msgs::OccupancyGrid msg;
  msg.info.width = 2;
  msg.info.height = 2;
  msg.info.resolution = 0.05f;
  msg.data.resize(3);
  EXPECT_THROW(fromOccupancyGrid(msg), std::invalid_argument);
  msg.data.resize(4);
  msg.info.resolution = 0.0f;
  EXPECT_THROW(fromOccupancyGrid(msg), std::invalid_argument);
}

}  // namespace
}  // namespace wheelchair_mapping
