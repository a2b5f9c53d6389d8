// rostest: the obstacle layer nodelet fuses /scan at the laser pose from tf only while
// /localization/status says localized, publishes /obstacles on /map's grid with the return's
// cell occupied, and clears it when free rays pass through the place again.
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_ros/conversions.h>

#include <cmath>

namespace {

/// 181 beams over 180 deg from the laser at (1, 1) facing +x: no return, except a person 2 m
/// ahead (the 5 middle beams) if `person`.
sensor_msgs::LaserScan scan(bool person) {
  sensor_msgs::LaserScan s;
  s.header.frame_id = "laser";
  s.header.stamp = ros::Time::now();
  s.angle_min = -M_PI / 2;
  s.angle_max = M_PI / 2;
  s.angle_increment = M_PI / 180;
  s.range_min = 0.05;
  s.range_max = 8.0;
  s.ranges.assign(181, INFINITY);
  if (person)
    for (int i = 88; i <= 92; ++i) s.ranges[i] = 2.0f;
  return s;
}

TEST(ObstacleLayerNode, PublishesWhatTheLocalizedLaserSeesAndClearsIt) {
  ros::NodeHandle nh;
  wheelchair_core::OccupancyMap room;  // 6 m x 4 m, walls on the border
  room.resolution = 0.05;
  room.width = 120;
  room.height = 80;
  room.data.assign(static_cast<size_t>(room.width) * room.height, wheelchair_core::kFree);
  for (int iy = 0; iy < room.height; ++iy)
    for (int ix = 0; ix < room.width; ++ix)
      if (ix == 0 || iy == 0 || ix == room.width - 1 || iy == room.height - 1)
        room.at(ix, iy) = wheelchair_core::kOccupied;
  ros::Publisher map_pub = nh.advertise<nav_msgs::OccupancyGrid>("/map", 1, true);
  ros::Publisher status_pub =
      nh.advertise<wheelchair_msgs::LocalizationStatus>("/localization/status", 1, true);
  ros::Publisher scan_pub = nh.advertise<sensor_msgs::LaserScan>("/scan", 10);
  nav_msgs::OccupancyGrid::ConstPtr layer;
  ros::Subscriber sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "/obstacles", 1, [&layer](const nav_msgs::OccupancyGrid::ConstPtr& m) { layer = m; });
  map_pub.publish(wheelchair_ros::toOccupancyGrid(room, "map", ros::Time::now()));
  wheelchair_msgs::LocalizationStatus status;
  status.state = wheelchair_msgs::LocalizationStatus::LOCALIZING;
  status.localized = false;
  status_pub.publish(status);
  int ix = -1, iy = -1;
  ASSERT_TRUE(room.worldToCell(3.0, 1.0, ix, iy));
  const auto person_seen = [&] {  // an obstacle cell within a cell of the return at (3, 1)
    if (!layer || layer->data.size() != room.data.size()) return false;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (layer->data[static_cast<size_t>(iy + dy) * room.width + ix + dx] ==
            wheelchair_core::kOccupied)
          return true;
    return false;
  };
  // Spins for `seconds`, scanning at 10 Hz, until `done`.
  const auto scanUntil = [&](bool person, double seconds, auto done) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end && !done()) {
      scan_pub.publish(scan(person));
      ros::WallDuration(0.1).sleep();
      ros::spinOnce();
    }
    return done();
  };
  EXPECT_FALSE(scanUntil(true, 3.0, person_seen)) << "fused while not localized";
  ASSERT_TRUE(layer) << "no /obstacles once /map arrived";
  EXPECT_EQ(layer->header.frame_id, "map");
  EXPECT_EQ(layer->info.width, static_cast<unsigned>(room.width));
  EXPECT_EQ(layer->info.height, static_cast<unsigned>(room.height));
  status.state = wheelchair_msgs::LocalizationStatus::LOCALIZED;
  status.localized = true;
  status_pub.publish(status);
  ASSERT_TRUE(scanUntil(true, 10.0, person_seen)) << "the person 2 m ahead never appeared";
  EXPECT_TRUE(scanUntil(false, 10.0, [&] { return !person_seen(); })) << "never cleared";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_obstacle_layer_node");
  return RUN_ALL_TESTS();
}
