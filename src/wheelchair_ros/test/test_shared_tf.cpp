// The process-wide tf buffer: one object for every caller while any holds it, filled by its
// listener from /tf, and released (listener thread stopped) with the last holder.
#include <wheelchair_ros/shared_tf.h>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>

namespace {

geometry_msgs::TransformStamped transform(double x) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = ros::Time::now();
  t.header.frame_id = "odom";
  t.child_frame_id = "base_link";
  t.transform.translation.x = x;
  t.transform.rotation.w = 1.0;
  return t;
}

TEST(SharedTf, OneBufferWhileHeld) {
  const auto first = wheelchair_ros::sharedTfBuffer();
  const auto second = wheelchair_ros::sharedTfBuffer();
  EXPECT_EQ(first.get(), second.get());
}

TEST(SharedTf, ReleasedWithTheLastHolder) {
  std::weak_ptr<tf2_ros::Buffer> weak = wheelchair_ros::sharedTfBuffer();
  EXPECT_TRUE(weak.expired());
}

TEST(SharedTf, ListenerFillsTheBuffer) {
  const auto buffer = wheelchair_ros::sharedTfBuffer();
  tf2_ros::TransformBroadcaster broadcaster;
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
  bool seen = false;
  while (!seen && ros::WallTime::now() < deadline) {  // until the subscription is connected
    broadcaster.sendTransform(transform(1.25));
    seen = buffer->canTransform("odom", "base_link", ros::Time(0), ros::Duration(0.2));
  }
  ASSERT_TRUE(seen);
  const auto other = wheelchair_ros::sharedTfBuffer();  // a second nodelet sees the same data
  EXPECT_DOUBLE_EQ(
      other->lookupTransform("odom", "base_link", ros::Time(0)).transform.translation.x, 1.25);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_shared_tf");
  ros::NodeHandle nh;  // keeps the node up between the tests
  return RUN_ALL_TESTS();
}
