// rostest: feeds the localizer node a map, tf and synthetic scans of a drive in the flat world
// (laserScanSimulator, noisy odometry) and checks /kld_pose and kld/localized against the truth.
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/String.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_kld/ros/conversions.h>
#include <wheelchair_kld/synthetic_drive.h>
#include <wheelchair_mapping/map_io.h>
#include <wheelchair_mapping/ros_conversions.h>

#include <cmath>

using namespace wheelchair_kld;

namespace {
geometry_msgs::TransformStamped transform(const mrpt::math::TPose2D& p, const std::string& parent,
                                          const std::string& child, const ros::Time& stamp) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  const auto pose = toPoseMsg(p);
  t.transform.translation.x = pose.position.x;
  t.transform.translation.y = pose.position.y;
  t.transform.rotation = pose.orientation;
  return t;
}
}  // namespace

TEST(KldLocalizerNode, TracksASyntheticDriveAndReportsLocalized) {
  ros::NodeHandle nh, pnh("~");
  std::string world;
  ASSERT_TRUE(pnh.getParam("world", world));
  const auto map = wheelchair_mapping::loadMap(world);
  const auto grid = loadWorldGrid(world);
  DriveParams dp;
  const auto drive = simulateDrive(grid, worldRoute("flat"), dp);

  geometry_msgs::PoseWithCovarianceStamped last_pose;
  std::string status;
  int poses = 0;
  auto pose_sub = nh.subscribe<geometry_msgs::PoseWithCovarianceStamped>(
      "kld_pose", 10, [&](const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& m) {
        last_pose = *m;
        ++poses;
      });
  auto status_sub = nh.subscribe<std_msgs::String>(
      "kld/localized", 10, [&](const std_msgs::String::ConstPtr& m) { status = m->data; });
  auto map_pub = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  auto scan_pub = nh.advertise<sensor_msgs::LaserScan>("scan", 10);
  auto init_pub = nh.advertise<geometry_msgs::PoseWithCovarianceStamped>("initialpose", 1, true);
  tf2_ros::StaticTransformBroadcaster static_tf;
  tf2_ros::TransformBroadcaster tf;
  static_tf.sendTransform(transform(dp.sensor_pose, "base_link", "laser", ros::Time::now()));
  map_pub.publish(wheelchair_mapping::toOccupancyGrid(map, "map", ros::Time::now()));
  // Wait for the localizer to subscribe and to have the map.
  for (int i = 0; i < 100 && (scan_pub.getNumSubscribers() == 0 || status == ""); ++i) {
    ros::Duration(0.05).sleep();
    ros::spinOnce();
  }
  ASSERT_GT(scan_pub.getNumSubscribers(), 0u);
  geometry_msgs::PoseWithCovarianceStamped init;
  init.header.frame_id = "map";
  init.header.stamp = ros::Time::now();
  init.pose.pose = toPoseMsg(drive[0].truth);
  init.pose.covariance[0] = init.pose.covariance[7] = 0.01;
  init.pose.covariance[35] = 0.0025;
  init_pub.publish(init);
  ros::Duration(0.3).sleep();

  const size_t n = std::min<size_t>(drive.size(), 120);
  double worst = 0;
  for (size_t i = 0; i < n; ++i) {
    const ros::Time stamp = ros::Time::now();
    tf.sendTransform(transform(drive[i].odom, "odom", "base_link", stamp));
    sensor_msgs::LaserScan scan;
    scan.header.stamp = stamp;
    scan.header.frame_id = "laser";
    scan.angle_min = drive[i].scan.angle_min;
    scan.angle_increment = drive[i].scan.angle_increment;
    scan.angle_max = scan.angle_min + scan.angle_increment * (drive[i].scan.ranges.size() - 1);
    scan.range_min = drive[i].scan.range_min;
    scan.range_max = drive[i].scan.range_max;
    scan.ranges = drive[i].scan.ranges;
    ros::Duration(0.01).sleep();
    scan_pub.publish(scan);
    ros::Duration(0.04).sleep();
    ros::spinOnce();
    if (poses > 0 && i > 10) {
      const auto p = toPose2D(last_pose.pose.pose);
      worst = std::max(worst, std::hypot(p.x - drive[i].truth.x, p.y - drive[i].truth.y));
    }
  }
  ros::Duration(0.2).sleep();
  ros::spinOnce();
  EXPECT_GT(poses, 20);
  EXPECT_EQ(last_pose.header.frame_id, "map");
  const auto p = toPose2D(last_pose.pose.pose);
  EXPECT_LT(std::hypot(p.x - drive[n - 1].truth.x, p.y - drive[n - 1].truth.y), 0.1);
  EXPECT_LT(worst, 0.25);
  EXPECT_EQ(status, "localized");
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_kld_localizer_node");
  ros::AsyncSpinner spinner(0);
  return RUN_ALL_TESTS();
}
