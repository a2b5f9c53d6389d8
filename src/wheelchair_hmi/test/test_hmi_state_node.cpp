// What the one-switch node publishes on /hmi/state (latched wheelchair_msgs/HmiState) while a
// rider scans, chooses, confirms and drives, against places_test.yaml: the kitchen (two places)
// first, then the hall and the bedroom; the sink, then the table.
#include <wheelchair_msgs/HmiState.h>

#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>

#include <wheelchair_msgs/GoToPlace.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "wait_for.h"

using wheelchair_msgs::HmiState;
using Strings = std::vector<std::string>;

namespace {

/// The latest /hmi/state and how many came, for as long as it lives.
struct LatestState {
  explicit LatestState(ros::NodeHandle& nh)
      : sub(nh.subscribe<HmiState>("hmi/state", 10, [this](const HmiState::ConstPtr& m) {
          msg = m;
          ++count;
        })) {}
  HmiState::ConstPtr msg;
  int count = 0;
  ros::Subscriber sub;
};

}  // namespace

TEST(HmiStateTopic, EveryStepOfAChoiceIsPublishedWithItsItemsAndHighlight) {
  ros::NodeHandle nh;
  LatestState latest(nh);
  const HmiState::ConstPtr& state = latest.msg;
  ros::Publisher press = nh.advertise<std_msgs::Empty>("switch", 1);
  ASSERT_TRUE(waitFor([&] { return state && press.getNumSubscribers() > 0; }))
      << "no latched /hmi/state";
  EXPECT_EQ(state->state, HmiState::SCANNING_ROOMS);
  EXPECT_EQ(state->items, (Strings{"kitchen", "hall", "bedroom"}));
  EXPECT_EQ(state->highlighted, 0);
  EXPECT_EQ(state->room, "kitchen");
  EXPECT_DOUBLE_EQ(state->step_time, 5.0);
  EXPECT_GT(state->time_left, 0.0);
  EXPECT_LE(state->time_left, 5.0);
  EXPECT_EQ(state->sentence, "kitchen?");

  // Not republished at 10 Hz: only when what it shows changes.
  const int before = latest.count;
  ros::WallDuration(1.0).sleep();
  ros::spinOnce();
  EXPECT_LE(latest.count - before, 1);

  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return state->state == HmiState::SCANNING_PLACES; }));
  EXPECT_EQ(state->items, (Strings{"sink", "table"}));
  EXPECT_EQ(state->highlighted, 0);
  EXPECT_EQ(state->room, "kitchen");
  EXPECT_EQ(state->place, "sink");
  EXPECT_EQ(state->sentence, "sink?");

  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return state->state == HmiState::CONFIRMING; }));
  EXPECT_EQ(state->place, "sink");
  EXPECT_EQ(state->items, (Strings{"sink"}));
  EXPECT_DOUBLE_EQ(state->step_time, 8.0);  // confirm_timeout
  EXPECT_EQ(state->sentence, "Go to sink? Press to confirm.");

  press.publish(std_msgs::Empty());
  ASSERT_TRUE(waitFor([&] { return state->state == HmiState::DRIVING; }));
  EXPECT_EQ(state->place, "sink");
  EXPECT_EQ(state->highlighted, -1);

  press.publish(std_msgs::Empty());  // a press while driving stops: scanning again
  ASSERT_TRUE(waitFor([&] { return state->state == HmiState::SCANNING_ROOMS; }));
  EXPECT_EQ(state->room, "kitchen");
}

TEST(HmiStateTopic, AGoalFromElsewhereIsDrivingNamedByItsPlaceOrNone) {
  ros::NodeHandle nh;
  LatestState latest(nh);
  const HmiState::ConstPtr& state = latest.msg;
  ros::Publisher goal_pub = nh.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 1);
  ASSERT_TRUE(waitFor([&] { return state && goal_pub.getNumSubscribers() > 0; }));
  geometry_msgs::PoseStamped goal;
  goal.header.frame_id = "map";
  goal.header.stamp = ros::Time::now();
  goal.pose.position.x = 8.0;  // the bed (yaw 0)
  goal.pose.position.y = 6.0;
  goal.pose.orientation.w = 1.0;
  goal_pub.publish(goal);
  ASSERT_TRUE(waitFor([&] { return state->state == HmiState::DRIVING; }));
  EXPECT_EQ(state->place, "bed");
  EXPECT_EQ(state->items, (Strings{"bed"}));

  goal.header.stamp = ros::Time::now();
  goal.pose.position.x = 6.5;  // a spot that is no place
  goal_pub.publish(goal);
  ASSERT_TRUE(waitFor([&] { return state->place.empty(); }));
  EXPECT_EQ(state->state, HmiState::DRIVING);
  EXPECT_TRUE(state->items.empty());
}

TEST(HmiStateTopic, APlaceSavedInThePlacesFileIsOfferedWithoutARestart) {
  ros::NodeHandle nh;
  LatestState latest(nh);
  const HmiState::ConstPtr& state = latest.msg;
  ros::Publisher finished = nh.advertise<std_msgs::Empty>("hmi/finished", 1);
  ASSERT_TRUE(waitFor([&] { return state && finished.getNumSubscribers() > 0; }));
  finished.publish(std_msgs::Empty());  // the drive of the test before ends: scanning rooms
  ASSERT_TRUE(waitFor([&] { return state->state == HmiState::SCANNING_ROOMS; }));
  EXPECT_EQ(state->items, (Strings{"kitchen", "hall", "bedroom"}));

  std::string path;
  ASSERT_TRUE(ros::param::get("/hmi/places_file", path));
  std::string text;
  {
    std::ifstream in(path);
    text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_NE(text.find("places:"), std::string::npos) << path;
  // As the display's carer tools write it: a new file renamed over the old one.
  std::ofstream(path + ".tmp") << text
                               << "  - {name: desk, room: study, x: 2.0, y: 7.0, yaw: 0.0}\n";
  ASSERT_EQ(std::rename((path + ".tmp").c_str(), path.c_str()), 0);

  ASSERT_TRUE(waitFor(
      [&] {
        return std::find(state->items.begin(), state->items.end(), "study") != state->items.end();
      },
      5.0))
      << "the saved place's room is not offered";
  EXPECT_EQ(state->items, (Strings{"kitchen", "hall", "bedroom", "study"}));
  wheelchair_msgs::GoToPlace srv;
  srv.request.name = "desk";
  ASSERT_TRUE(ros::service::call("go_to_place", srv));
  EXPECT_TRUE(srv.response.accepted) << srv.response.message;
  std::remove(path.c_str());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_hmi_state_node");
  return RUN_ALL_TESTS();
}
