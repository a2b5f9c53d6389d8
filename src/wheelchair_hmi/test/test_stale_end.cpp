// The end of the rider's previous drive, arriving after the next goal was sent, must not end
// the new drive: the rider chose the sink, then the table before the sink's result came; the
// navigator (played here) answers the sink late. Only the table's words and result count.
#include <wheelchair_msgs/GoToPlace.h>

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/String.h>

#include <algorithm>

#include "fake_navigator.h"
#include "wait_for.h"

namespace {

TEST(StaleEnd, ThePreviousGoalsLateResultDoesNotEndTheNewDrive) {
  ros::NodeHandle nh;
  FakeNavigator navigator(nh);
  std::vector<std::string> announced;
  auto sub = nh.subscribe<std_msgs::String>(
      "hmi/announce", 20,
      [&](const std_msgs::String::ConstPtr& m) { announced.push_back(m->data); });
  const auto told = [&](const std::string& text) {
    return std::find(announced.begin(), announced.end(), text) != announced.end();
  };
  ASSERT_TRUE(ros::service::waitForService("go_to_place", ros::Duration(10.0)));
  wheelchair_msgs::GoToPlace srv;
  srv.request.name = "sink";
  ASSERT_TRUE(ros::service::call("go_to_place", srv));
  ASSERT_TRUE(waitFor([&] { return navigator.goals.size() == 1; }));
  navigator.say(0, "Going to sink: 3.1 m.");
  ASSERT_TRUE(waitFor([&] { return told("Going to sink: 3.1 m."); }));
  srv.request.name = "table";
  ASSERT_TRUE(ros::service::call("go_to_place", srv));
  ASSERT_TRUE(waitFor([&] { return navigator.goals.size() == 2; }));
  EXPECT_EQ(navigator.goals[1].getGoal()->place, "table");
  // The sink's end comes now, late: as the navigator ends a replaced goal, and as an arrival.
  navigator.say(0, "Stale words about the sink.");
  navigator.end(0, wheelchair_msgs::NavigateResult::REACHED, "Arrived.");
  navigator.say(1, "Going to table: 2.0 m.");
  ASSERT_TRUE(waitFor([&] { return told("Going to table: 2.0 m."); }));
  EXPECT_FALSE(told("Arrived.")) << "the sink's result ended the table's drive";
  EXPECT_FALSE(told("Stale words about the sink."));
  const size_t before = announced.size();
  waitFor([] { return false; }, 0.5);
  for (size_t i = before; i < announced.size(); ++i)
    EXPECT_NE(announced[i].back(), '?') << "scanning restarted during the drive: " << announced[i];
  navigator.end(1, wheelchair_msgs::NavigateResult::REACHED, "Arrived.");
  EXPECT_TRUE(waitFor([&] { return told("Arrived."); }));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_hmi_stale_end");
  return RUN_ALL_TESTS();
}
