// The supervisor nodelet in a live graph: healthy data keeps it quiet; a person stepping onto
// the path, or a silent laser, stops the chair with the reason (scenario from ~scenario).
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/SafetyStatus.h>

#include <cmath>

namespace {

/// Feeds the supervisor a chair at (2, 2) facing +x on a straight path in a free 10 x 4 m map.
class World {
 public:
  World() {
    map_pub_ = nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    plan_pub_ = nh_.advertise<nav_msgs::Path>("plan", 1, true);
    pose_pub_ = nh_.advertise<geometry_msgs::PoseWithCovarianceStamped>("kld_pose", 1);
    localized_pub_ = nh_.advertise<wheelchair_msgs::LocalizationStatus>("localization/status", 1);
    scan_pub_ = nh_.advertise<sensor_msgs::LaserScan>("scan", 1);
    stop_sub_ = nh_.subscribe<std_msgs::Bool>(
        "safety/stop", 5, [this](const std_msgs::Bool::ConstPtr& m) { stop_ = m->data; });
    status_sub_ = nh_.subscribe<wheelchair_msgs::SafetyStatus>(
        "safety/status", 5,
        [this](const wheelchair_msgs::SafetyStatus::ConstPtr& m) { status_ = *m; });
    nav_msgs::OccupancyGrid map;
    map.header.frame_id = "map";
    map.info.resolution = 0.05;
    map.info.width = 200;
    map.info.height = 80;
    map.info.origin.orientation.w = 1.0;
    map.data.assign(200 * 80, 0);
    map_pub_.publish(map);
    nav_msgs::Path plan;
    plan.header.frame_id = "map";
    for (double x = 1.0; x <= 8.5; x += 0.1) {
      geometry_msgs::PoseStamped p;
      p.pose.position.x = x;
      p.pose.position.y = 2.0;
      p.pose.orientation.w = 1.0;
      plan.poses.push_back(p);
    }
    plan_pub_.publish(plan);
  }

  /// One 10 Hz cycle of healthy data; the scan shows a person 0.9 m ahead if asked.
  void cycle(bool scan, bool person) {
    const ros::Time now = ros::Time::now();
    geometry_msgs::TransformStamped tf;
    tf.header.stamp = now;
    tf.header.frame_id = "map";
    tf.child_frame_id = "base_link";
    tf.transform.translation.x = 2.0;
    tf.transform.translation.y = 2.0;
    tf.transform.rotation.w = 1.0;
    broadcaster_.sendTransform(tf);
    tf.child_frame_id = "laser";
    tf.header.frame_id = "base_link";
    tf.transform.translation.x = 0.0;
    tf.transform.translation.y = 0.0;
    broadcaster_.sendTransform(tf);
    geometry_msgs::PoseWithCovarianceStamped pose;
    pose.header.stamp = now;
    pose.header.frame_id = "map";
    pose.pose.covariance[0] = pose.pose.covariance[7] = pose.pose.covariance[35] = 1e-3;
    pose_pub_.publish(pose);
    wheelchair_msgs::LocalizationStatus localized;
    localized.header.stamp = now;
    localized.state = wheelchair_msgs::LocalizationStatus::LOCALIZED;
    localized.localized = true;
    localized_pub_.publish(localized);
    if (!scan) return;
    sensor_msgs::LaserScan s;
    s.header.stamp = now;
    s.header.frame_id = "laser";
    s.angle_min = -M_PI / 2;
    s.angle_increment = M_PI / 360;
    s.range_min = 0.05;
    s.range_max = 10.0;
    s.ranges.assign(361, std::numeric_limits<float>::infinity());
    if (person)
      for (int i = 170; i <= 190; ++i) s.ranges[i] = 0.9f;  // +-5 deg straight ahead
    scan_pub_.publish(s);
  }

  /// Runs cycles for `seconds`; returns true when the stop flag became `want`.
  bool runUntil(double seconds, bool scan, bool person, bool want) {
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      cycle(scan, person);
      ros::WallDuration(0.1).sleep();
      ros::spinOnce();
      if (stop_ == want && ready_) return true;
      ready_ = stop_ != -1;
    }
    return false;
  }

  int stop_ = -1;
  bool ready_ = false;
  wheelchair_msgs::SafetyStatus status_;

 private:
  ros::NodeHandle nh_;
  ros::Publisher map_pub_, plan_pub_, pose_pub_, localized_pub_, scan_pub_;
  ros::Subscriber stop_sub_, status_sub_;
  tf2_ros::TransformBroadcaster broadcaster_;
};

}  // namespace

TEST(SafetyNode, ScenarioStopsWithItsReason) {
  std::string scenario;
  ros::param::param<std::string>("~scenario", scenario, "person");
  World world;
  ASSERT_TRUE(world.runUntil(15.0, true, false, false)) << "healthy data: " << world.status_;
  EXPECT_EQ(world.status_.reason, wheelchair_msgs::SafetyStatus::NONE) << world.status_;
  EXPECT_FALSE(world.status_.stop);
  if (scenario == "person") {
    ASSERT_TRUE(world.runUntil(5.0, true, true, true));
    EXPECT_EQ(world.status_.reason, wheelchair_msgs::SafetyStatus::OBSTACLE) << world.status_;
    EXPECT_NE(world.status_.sentence.find("in the way"), std::string::npos) << world.status_;
    ASSERT_FALSE(world.runUntil(1.0, true, false, false)) << "resumed without a command";
  } else {
    const ros::WallTime silent = ros::WallTime::now();
    ASSERT_TRUE(world.runUntil(5.0, false, false, true));
    EXPECT_LT((ros::WallTime::now() - silent).toSec(), 0.3 + 0.35);  // timeout + 2 cycles
    EXPECT_EQ(world.status_.reason, wheelchair_msgs::SafetyStatus::LASER_SILENT) << world.status_;
    EXPECT_NE(world.status_.sentence.find("laser scanner is silent"), std::string::npos)
        << world.status_;
    EXPECT_GT(world.status_.value, world.status_.limit) << world.status_;  // age > scan_timeout
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_safety_node");
  return RUN_ALL_TESTS();
}
