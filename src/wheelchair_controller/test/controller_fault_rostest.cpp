// rostest: the controller nodelet tracks a path (tf map->base_link and /odom fed here), then
// gets a fault (~fault: nan_path | stale_pose) and must command zero torque + brake and
// report "aborted: <reason>" on ~status.
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/String.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_msgs/WheelTorques.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <string>

namespace {

nav_msgs::Path straightPath(double nan_at = -1.0) {
  nav_msgs::Path path;
  path.header.frame_id = "map";
  path.header.stamp = ros::Time::now();
  for (int i = 0; i <= 60; ++i) {
    geometry_msgs::PoseStamped p;
    p.header = path.header;
    p.pose.position.x = (i == nan_at) ? NAN : 0.05 * i;
    p.pose.orientation.w = 1.0;
    path.poses.push_back(p);
  }
  return path;
}

bool waitFor(const std::function<bool()>& condition, double timeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (condition()) return true;
    ros::WallDuration(0.01).sleep();
  }
  return condition();
}

}  // namespace

TEST(ControllerNodelet, FaultEndsInZeroTorqueAndBrake) {
  ros::NodeHandle nh, pnh("~");
  const std::string fault = pnh.param<std::string>("fault", "nan_path");
  wheelchair_msgs::WheelTorques last;
  std::atomic<int> count{0};
  std::string status;
  ros::Subscriber torque_sub = nh.subscribe<wheelchair_msgs::WheelTorques>(
      "wheel_torques", 10, [&](const wheelchair_msgs::WheelTorques::ConstPtr& m) {
        last = *m;
        ++count;
      });
  ros::Subscriber status_sub = nh.subscribe<std_msgs::String>(
      "controller/status", 10, [&](const std_msgs::String::ConstPtr& m) { status = m->data; });
  ros::Publisher path_pub = nh.advertise<nav_msgs::Path>("plan", 1, true);
  ros::Publisher odom_pub = nh.advertise<nav_msgs::Odometry>("odom", 10);
  tf2_ros::TransformBroadcaster tf;
  std::atomic<bool> publish_pose{true};
  // The chair stands still at the origin: tf and /odom at 50 Hz.
  ros::Timer feed = nh.createTimer(ros::Duration(0.02), [&](const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    if (publish_pose) {
      geometry_msgs::TransformStamped t;
      t.header.stamp = now;
      t.header.frame_id = "map";
      t.child_frame_id = "base_link";
      t.transform.rotation.w = 1.0;
      tf.sendTransform(t);
    }
    nav_msgs::Odometry odom;
    odom.header.stamp = now;
    odom.pose.pose.orientation.w = 1.0;
    odom_pub.publish(odom);
  });
  ros::AsyncSpinner spinner(2);
  spinner.start();

  ASSERT_TRUE(waitFor([&] { return count > 10; }, 20.0)) << "no /wheel_torques";
  EXPECT_TRUE(last.brake) << "idle controller holds the brake";
  path_pub.publish(straightPath());
  ASSERT_TRUE(waitFor([&] { return !last.brake && std::abs(last.left) > 1e-3; }, 5.0))
      << "the controller does not start tracking; status: " << status;

  if (fault == "nan_path") {
    path_pub.publish(straightPath(30));
  } else {
    publish_pose = false;
  }
  EXPECT_TRUE(waitFor([&] { return last.brake && last.left == 0.0 && last.right == 0.0; }, 6.0))
      << "status: " << status;
  EXPECT_TRUE(waitFor([&] { return status.rfind("aborted", 0) == 0; }, 1.0)) << status;
  const std::string expected = fault == "nan_path" ? "non-finite" : "stale pose";
  EXPECT_NE(status.find(expected), std::string::npos) << status;
  // It stays stopped.
  ros::WallDuration(0.5).sleep();
  EXPECT_TRUE(last.brake);
  EXPECT_EQ(last.left, 0.0);
  EXPECT_EQ(last.right, 0.0);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "controller_fault_rostest");
  return RUN_ALL_TESTS();
}
