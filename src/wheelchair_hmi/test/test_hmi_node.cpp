// The one-switch node driven by scripted switch events, as an adapter would publish them.
#include <wheelchair_msgs/GoToPlace.h>

#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>

#include "wait_for.h"

TEST(HmiNode, ThreePressesSendTheKitchenSinkAsGoalAndAFourthStops) {
  ros::NodeHandle nh;
  geometry_msgs::PoseStamped::ConstPtr goal;
  std::string announced;
  int stops = 0;
  auto goal_sub = nh.subscribe<geometry_msgs::PoseStamped>(
      "move_base_simple/goal", 1, [&](const geometry_msgs::PoseStamped::ConstPtr& m) { goal = m; });
  auto text_sub = nh.subscribe<std_msgs::String>(
      "hmi/announce", 10, [&](const std_msgs::String::ConstPtr& m) { announced = m->data; });
  auto stop_sub = nh.subscribe<std_msgs::Empty>("user_stop", 1,
                                                [&](const std_msgs::Empty::ConstPtr&) { ++stops; });
  ros::Publisher press = nh.advertise<std_msgs::Empty>("switch", 1);
  ASSERT_TRUE(waitFor([&] { return announced == "kitchen?" && press.getNumSubscribers() > 0; }))
      << "first highlight was '" << announced << "'";  // the largest room comes first
  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return announced == "sink?"; })) << announced;
  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return announced.rfind("Go to sink?", 0) == 0; })) << announced;
  EXPECT_FALSE(goal) << "a goal before the confirmation";
  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return goal != nullptr; }));
  EXPECT_EQ(goal->header.frame_id, "map");
  EXPECT_DOUBLE_EQ(goal->pose.position.x, 4.0);
  EXPECT_DOUBLE_EQ(goal->pose.position.y, 2.0);
  EXPECT_NEAR(2.0 * std::atan2(goal->pose.orientation.z, goal->pose.orientation.w), 1.5708, 1e-6);
  press.publish(std_msgs::Empty());  // while driving: stop
  EXPECT_TRUE(waitFor([&] { return stops == 1; }));
}

TEST(HmiNode, UnknownPlaceIsRefusedWithAMessage) {
  ros::NodeHandle nh;
  ASSERT_TRUE(ros::service::waitForService("go_to_place", ros::Duration(10.0)));
  wheelchair_msgs::GoToPlace srv;
  srv.request.name = "garage";
  ASSERT_TRUE(ros::service::call("go_to_place", srv));
  EXPECT_FALSE(srv.response.accepted);
  EXPECT_NE(srv.response.message.find("garage"), std::string::npos);
  srv.request.name = "bed";
  ASSERT_TRUE(ros::service::call("go_to_place", srv));
  EXPECT_TRUE(srv.response.accepted);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_hmi_node");
  return RUN_ALL_TESTS();
}
