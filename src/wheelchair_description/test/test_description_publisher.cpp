// rostest: what description_publisher puts on the parameter server and on tf.
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/transform_listener.h>
#include <urdf/model.h>
#include <wheelchair_ros/conversions.h>

#include <atomic>
#include <cmath>

using namespace wheelchair_description;

namespace {

geometry_msgs::TransformStamped waitForTransform(tf2_ros::Buffer& buffer, const std::string& parent,
                                                 const std::string& child) {
  return buffer.lookupTransform(parent, child, ros::Time(0), ros::Duration(15.0));
}

}  // namespace

TEST(DescriptionPublisher, RobotDescriptionIsSetAndParses) {
  std::string xml;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(15.0);
  while (!ros::param::get("/robot_description", xml) && ros::WallTime::now() < deadline)
    ros::WallDuration(0.1).sleep();
  ASSERT_FALSE(xml.empty()) << "/robot_description was not set";
  urdf::Model model;
  ASSERT_TRUE(model.initString(xml));
  EXPECT_TRUE(model.getJoint("left_wheel_joint"));
  EXPECT_TRUE(model.getJoint("right_wheel_joint"));
}

TEST(DescriptionPublisher, LaserMountArrivesOnTf) {
  const ChairParams p = test::shippedChair();
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  const auto laser = waitForTransform(buffer, "base_link", "laser");
  EXPECT_NEAR(laser.transform.translation.x, p.laser_x, 1e-9);
  EXPECT_NEAR(laser.transform.translation.y, p.laser_y, 1e-9);
  EXPECT_NEAR(laser.transform.translation.z, p.laser_z, 1e-9);
  EXPECT_NEAR(wheelchair_ros::yawOf(laser.transform.rotation), p.laser_yaw, 1e-9);
  // The rear laser, looking behind the chair (it guards reverse motion).
  const auto rear = waitForTransform(buffer, "base_link", "rear_laser");
  EXPECT_NEAR(rear.transform.translation.x, p.rear_laser_x, 1e-9);
  EXPECT_NEAR(rear.transform.translation.z, p.rear_laser_z, 1e-9);
  EXPECT_NEAR(
      std::remainder(wheelchair_ros::yawOf(rear.transform.rotation) - p.rear_laser_yaw, 2 * M_PI),
      0.0, 1e-9);
  const auto base = waitForTransform(buffer, "base_footprint", "base_link");
  EXPECT_NEAR(base.transform.translation.z, p.wheel_radius, 1e-9);
  // The whole chair, floor to sensor, in one tree.
  const auto floor_to_laser = waitForTransform(buffer, "base_footprint", "laser");
  EXPECT_NEAR(floor_to_laser.transform.translation.z, p.wheel_radius + p.laser_z, 1e-9);
}

TEST(DescriptionPublisher, WheelsStartAtZeroAndFollowJointStates) {
  const ChairParams p = test::shippedChair();
  tf2_ros::Buffer buffer;
  tf2_ros::TransformListener listener(buffer);
  const auto at_rest = waitForTransform(buffer, "base_link", "left_wheel");
  EXPECT_NEAR(at_rest.transform.translation.y, p.half_track, 1e-9);
  EXPECT_NEAR(at_rest.transform.rotation.w, 1.0, 1e-9);

  ros::NodeHandle nh;
  ros::Publisher pub = nh.advertise<sensor_msgs::JointState>("joint_states", 1);
  const double angle = 0.7;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(15.0);
  double seen = 0.0;
  while (ros::WallTime::now() < deadline) {
    sensor_msgs::JointState msg;
    msg.header.stamp = ros::Time::now();
    msg.name = {"left_wheel_joint", "right_wheel_joint"};
    msg.position = {angle, -angle};
    pub.publish(msg);
    ros::WallDuration(0.1).sleep();
    const auto left = buffer.lookupTransform("base_link", "left_wheel", ros::Time(0));
    // A rotation by angle about +y: q = (0, sin(angle/2), 0, cos(angle/2)).
    seen = 2.0 * std::atan2(left.transform.rotation.y, left.transform.rotation.w);
    if (std::abs(seen - angle) < 1e-9) break;
  }
  EXPECT_NEAR(seen, angle, 1e-9);
  const auto right = buffer.lookupTransform("base_link", "right_wheel", ros::Time(0));
  EXPECT_NEAR(2.0 * std::atan2(right.transform.rotation.y, right.transform.rotation.w), -angle,
              1e-9);
  EXPECT_NEAR(right.transform.translation.y, -p.half_track, 1e-9);
}

// Every /tf message wakes every tf listener: the wheels (for rviz only) go out at most at
// ~publish_frequency (default 20 Hz), not at each of the base driver's 50 Hz /joint_states.
TEST(DescriptionPublisher, WheelJointsAtMostAtPublishFrequency) {
  ros::NodeHandle nh;
  std::atomic<int> wheel_messages{0};
  ros::Subscriber sub =
      nh.subscribe<tf2_msgs::TFMessage>("/tf", 100, [&](const tf2_msgs::TFMessage::ConstPtr& msg) {
        for (const auto& t : msg->transforms)
          if (t.child_frame_id == "left_wheel") ++wheel_messages;
      });
  ros::Publisher pub = nh.advertise<sensor_msgs::JointState>("joint_states", 10);
  const ros::WallTime connect_deadline = ros::WallTime::now() + ros::WallDuration(10.0);
  while ((pub.getNumSubscribers() == 0 || sub.getNumPublishers() == 0) &&
         ros::WallTime::now() < connect_deadline)
    ros::WallDuration(0.05).sleep();
  const double seconds = 2.0, joint_rate = 50.0, publish_frequency = 20.0;
  ros::WallDuration(0.2).sleep();
  wheel_messages = 0;
  for (int i = 0; i < static_cast<int>(seconds * joint_rate); ++i) {
    sensor_msgs::JointState msg;
    msg.header.stamp = ros::Time::now();
    msg.name = {"left_wheel_joint", "right_wheel_joint"};
    msg.position = {0.01 * i, -0.01 * i};
    pub.publish(msg);
    ros::WallDuration(1.0 / joint_rate).sleep();
  }
  ros::WallDuration(0.1).sleep();
  EXPECT_LE(wheel_messages, seconds * publish_frequency + 2);  // was one per joint_states: 100
  EXPECT_GE(wheel_messages, seconds * publish_frequency / 2);  // still following them
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_description_publisher");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
