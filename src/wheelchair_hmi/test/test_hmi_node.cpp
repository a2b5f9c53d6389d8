// The one-switch node driven by scripted switch events, as an adapter would publish them, with
// the navigator played by the test: the chosen place is the navigator's goal, its words and its
// result are what the rider hears, a press while driving stops the chair.
#include <wheelchair_msgs/GoToPlace.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/NavigatorState.h>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>

#include <algorithm>

#include "fake_navigator.h"
#include "wait_for.h"

namespace {

class HmiNode : public testing::Test {
 protected:
  HmiNode() : navigator(nh) {
    text_sub = nh.subscribe<std_msgs::String>(
        "hmi/announce", 20,
        [this](const std_msgs::String::ConstPtr& m) { announced.push_back(m->data); });
    stop_sub = nh.subscribe<std_msgs::Empty>("user_stop", 5,
                                             [this](const std_msgs::Empty::ConstPtr&) { ++stops; });
  }
  bool told(const std::string& text) const {
    return std::find(announced.begin(), announced.end(), text) != announced.end();
  }
  /// Restarts the HMI's scanning (a drive a previous test left), waits for a highlight.
  void scanning() {
    ros::Publisher finished = nh.advertise<std_msgs::Empty>("hmi/finished", 1);
    ASSERT_TRUE(waitFor([&] { return finished.getNumSubscribers() > 0; }));
    finished.publish(std_msgs::Empty());
    ASSERT_TRUE(waitFor([&] { return !announced.empty() && announced.back().back() == '?'; }));
  }

  ros::NodeHandle nh;
  FakeNavigator navigator;
  std::vector<std::string> announced;
  int stops = 0;
  ros::Subscriber text_sub, stop_sub;
};

TEST_F(HmiNode, ThreePressesSendTheKitchenSinkToTheNavigatorAndAFourthStops) {
  ros::Publisher press = nh.advertise<std_msgs::Empty>("switch", 1);
  ASSERT_TRUE(waitFor([&] {
    return !announced.empty() && announced.back() == "kitchen?" && press.getNumSubscribers() > 0;
  })) << "first highlight was '"
      << (announced.empty() ? "" : announced.back()) << "'";
  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return announced.back() == "sink?"; })) << announced.back();
  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return announced.back().rfind("Go to sink?", 0) == 0; }));
  EXPECT_TRUE(navigator.goals.empty()) << "a goal before the confirmation";
  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return navigator.goals.size() == 1; }));
  const auto goal = navigator.goals[0].getGoal();
  EXPECT_EQ(goal->place, "sink");
  EXPECT_EQ(goal->target_pose.header.frame_id, "map");
  EXPECT_DOUBLE_EQ(goal->target_pose.pose.position.x, 4.0);
  EXPECT_DOUBLE_EQ(goal->target_pose.pose.position.y, 2.0);
  const auto& q = goal->target_pose.pose.orientation;
  EXPECT_NEAR(2.0 * std::atan2(q.z, q.w), 1.5708, 1e-6);
  navigator.say(0, "Going to sink: 3.1 m.");
  ASSERT_TRUE(waitFor([&] { return told("Going to sink: 3.1 m."); }));
  press.publish(std_msgs::Empty());  // while driving: stop
  EXPECT_TRUE(waitFor([&] { return stops == 1 && navigator.cancels.size() == 1; }))
      << stops << " stops, " << navigator.cancels.size() << " cancels";
}

TEST_F(HmiNode, UnknownPlaceIsRefusedWithAMessage) {
  ASSERT_TRUE(ros::service::waitForService("go_to_place", ros::Duration(10.0)));
  wheelchair_msgs::GoToPlace srv;
  srv.request.name = "garage";
  ASSERT_TRUE(ros::service::call("go_to_place", srv));
  EXPECT_FALSE(srv.response.accepted);
  EXPECT_NE(srv.response.message.find("garage"), std::string::npos);
  EXPECT_TRUE(navigator.goals.empty());
}

TEST_F(HmiNode, TheNavigatorsWordsAreToldAndItsResultEndsTheDrive) {
  scanning();
  wheelchair_msgs::GoToPlace srv;
  srv.request.name = "bed";
  ASSERT_TRUE(ros::service::call("go_to_place", srv));
  ASSERT_TRUE(waitFor([&] { return navigator.goals.size() == 1; }));
  navigator.say(0, "Something is in the way: waiting for it to move.",
                wheelchair_msgs::NavigatorState::WAITING);
  EXPECT_TRUE(waitFor([&] { return told("Something is in the way: waiting for it to move."); }));
  navigator.say(0, "Stopping.", wheelchair_msgs::NavigatorState::STOPPING);
  const size_t before = announced.size();
  navigator.end(0, wheelchair_msgs::NavigateResult::SAFETY_STOP,
                "Safety stop: the laser scanner is silent. Choose a destination to go on.");
  ASSERT_TRUE(waitFor([&] {
    return told("Safety stop: the laser scanner is silent. Choose a destination to go on.");
  }));
  EXPECT_FALSE(told("Stopping.")) << "the stop itself is not news";
  // Scanning again: the next highlight follows the result.
  EXPECT_TRUE(
      waitFor([&] { return announced.size() > before + 1 && announced.back().back() == '?'; }));
}

TEST_F(HmiNode, ADriveStartedElsewhereMakesAPressStopIt) {
  scanning();
  ros::Publisher state = nh.advertise<wheelchair_msgs::NavigatorState>("navigator/state", 1, true);
  ros::Publisher press = nh.advertise<std_msgs::Empty>("switch", 1);
  ASSERT_TRUE(
      waitFor([&] { return state.getNumSubscribers() > 0 && press.getNumSubscribers() > 0; }));
  wheelchair_msgs::NavigatorState s;
  s.state = wheelchair_msgs::NavigatorState::DRIVING;
  s.active = true;
  s.goal_id = "rviz-1";
  s.sentence = "Going: 4.2 m.";
  state.publish(s);
  ASSERT_TRUE(waitFor([&] { return told("The chair is moving. Press to stop."); }));
  EXPECT_TRUE(waitFor([&] { return told("Going: 4.2 m."); }));
  const int before = stops;
  press.publish(std_msgs::Empty());
  EXPECT_TRUE(waitFor([&] { return stops == before + 1; }));
}

TEST_F(HmiNode, ALostPositionIsToldWhileTheRiderChooses) {
  scanning();
  ros::Publisher localization =
      nh.advertise<wheelchair_msgs::LocalizationStatus>("localization/status", 5);
  ASSERT_TRUE(waitFor([&] { return localization.getNumSubscribers() > 0; }));
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

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_hmi_node");
  return RUN_ALL_TESTS();
}
