// The one-switch node driven by scripted switch events, as an adapter would publish them, and
// what it tells the rider of the supervisor's and the localizer's typed statuses.
#include <wheelchair_msgs/GoToPlace.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/SafetyStatus.h>

#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>

#include <algorithm>

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

TEST(HmiNode, ASafetyStopWhileDrivingIsToldInTheSupervisorsWords) {
  ros::NodeHandle nh;
  std::vector<std::string> announced;  // every one: the next highlight follows the stop at once
  auto text_sub = nh.subscribe<std_msgs::String>(
      "hmi/announce", 10,
      [&](const std_msgs::String::ConstPtr& m) { announced.push_back(m->data); });
  const auto told = [&](const std::string& text) {
    return std::find(announced.begin(), announced.end(), text) != announced.end();
  };
  ros::Publisher safety = nh.advertise<wheelchair_msgs::SafetyStatus>("safety/status", 1);
  ASSERT_TRUE(waitFor([&] { return safety.getNumSubscribers() > 0; }));
  wheelchair_msgs::GoToPlace srv;
  srv.request.name = "sink";
  ASSERT_TRUE(ros::service::call("go_to_place", srv));  // the chair drives
  ASSERT_TRUE(waitFor([&] { return told("Going to sink."); }));
  wheelchair_msgs::SafetyStatus status;
  status.header.stamp = ros::Time::now();
  status.stop = true;
  status.reason = wheelchair_msgs::SafetyStatus::OBSTACLE;
  status.sentence = "something is in the way";
  status.detail = "5 laser returns on the path ahead";
  safety.publish(status);
  EXPECT_TRUE(waitFor([&] {
    return told("Safety stop: something is in the way. Choose a destination to go on.");
  }));
}

TEST(HmiNode, ALostPositionIsToldWhileTheRiderChooses) {
  ros::NodeHandle nh;
  std::vector<std::string> announced;
  auto text_sub = nh.subscribe<std_msgs::String>(
      "hmi/announce", 10,
      [&](const std_msgs::String::ConstPtr& m) { announced.push_back(m->data); });
  ros::Publisher localization =
      nh.advertise<wheelchair_msgs::LocalizationStatus>("localization/status", 5);
  ASSERT_TRUE(waitFor([&] { return localization.getNumSubscribers() > 0; }));
  const auto told = [&](const std::string& text) {
    return std::find(announced.begin(), announced.end(), text) != announced.end();
  };
  wheelchair_msgs::LocalizationStatus status;
  status.state = wheelchair_msgs::LocalizationStatus::MISFIT;
  status.localized = false;
  status.sentence = "The chair does not know where it is.";
  localization.publish(status);
  EXPECT_TRUE(waitFor([&] { return told(status.sentence); }));
  localization.publish(status);  // the same verdict again is not news
  status.state = wheelchair_msgs::LocalizationStatus::LOCALIZED;
  status.localized = true;
  status.sentence = "The chair knows where it is.";
  localization.publish(status);
  EXPECT_TRUE(waitFor([&] { return told(status.sentence); }));
  EXPECT_EQ(std::count(announced.begin(), announced.end(), "The chair does not know where it is."),
            1);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_hmi_node");
  return RUN_ALL_TESTS();
}
