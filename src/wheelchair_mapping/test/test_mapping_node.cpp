// rostest: the mapping node fuses /scan at the laser pose from tf2 and publishes /map in the
// pose frame; ~save_map writes a map file with the same content.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_ros/conversions.h>

#include <cmath>

#include "map_test_files.h"

namespace wheelchair_mapping {
namespace {

constexpr double kX = 1.0, kY = 2.0, kYaw = 0.5, kWall = 3.0;

sensor_msgs::LaserScan circleScan() {
  sensor_msgs::LaserScan s;
  s.header.frame_id = "laser";
  s.header.stamp = ros::Time::now();
  s.angle_min = -M_PI / 2;
  s.angle_max = M_PI / 2;
  s.angle_increment = M_PI / 180;
  s.range_min = 0.05;
  s.range_max = 8.0;
  s.ranges.assign(181, kWall);  // a circular wall 3 m around the laser
  return s;
}

int8_t cellAt(const wheelchair_core::OccupancyMap& m, double x, double y) {
  int ix, iy;
  return m.worldToCell(x, y, ix, iy) ? m.at(ix, iy) : -2;
}

TEST(MappingNode, BuildsPublishesAndSavesTheMap) {
  ros::NodeHandle nh;
  tf2_ros::StaticTransformBroadcaster tf;
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "odom";
  t.child_frame_id = "laser";
  t.transform.translation.x = kX;
  t.transform.translation.y = kY;
  t.transform.rotation.z = std::sin(kYaw / 2);
  t.transform.rotation.w = std::cos(kYaw / 2);
  tf.sendTransform(t);

  nav_msgs::OccupancyGrid::ConstPtr map;
  ros::Subscriber sub = nh.subscribe<nav_msgs::OccupancyGrid>(
      "/map", 1, [&map](const nav_msgs::OccupancyGrid::ConstPtr& m) { map = m; });
  ros::Publisher scans = nh.advertise<sensor_msgs::LaserScan>("/scan", 10);
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(30.0);
  while (!map && ros::ok() && ros::WallTime::now() < end) {
    scans.publish(circleScan());
    ros::WallDuration(0.1).sleep();
    ros::spinOnce();
  }
  ASSERT_TRUE(map) << "no /map within 30 s";
  EXPECT_EQ(map->header.frame_id, "odom");
  const wheelchair_core::OccupancyMap m = wheelchair_ros::fromOccupancyGrid(*map);
  // Ahead of the laser (its yaw in odom): free, then the wall; behind it: unknown.
  EXPECT_EQ(cellAt(m, kX + 1.5 * std::cos(kYaw), kY + 1.5 * std::sin(kYaw)),
            wheelchair_core::kFree);
  EXPECT_EQ(cellAt(m, kX + (kWall + 0.01) * std::cos(kYaw), kY + (kWall + 0.01) * std::sin(kYaw)),
            wheelchair_core::kOccupied);
  EXPECT_EQ(cellAt(m, kX - 1.5 * std::cos(kYaw), kY - 1.5 * std::sin(kYaw)),
            wheelchair_core::kUnknown);

  wheelchair_core::test::TempDir dir;
  ros::param::set("/mapping/save_path", dir.file("saved.yaml"));
  std_srvs::Trigger save;
  ASSERT_TRUE(ros::service::waitForService("/mapping/save_map", ros::Duration(10.0)));
  ASSERT_TRUE(ros::service::call("/mapping/save_map", save));
  EXPECT_TRUE(save.response.success) << save.response.message;
  const wheelchair_core::OccupancyMap saved = wheelchair_core::loadMap(dir.file("saved.yaml"));
  EXPECT_EQ(
      cellAt(saved, kX + (kWall + 0.01) * std::cos(kYaw), kY + (kWall + 0.01) * std::sin(kYaw)),
      wheelchair_core::kOccupied);
}

}  // namespace
}  // namespace wheelchair_mapping

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_mapping_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
