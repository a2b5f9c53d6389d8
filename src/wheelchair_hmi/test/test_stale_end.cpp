// The HMI against the controller's late statuses: the previous drive's "goal_reached" (or
// "aborted") arriving after a new goal was sent, before the new path reached the controller,
// must not end the new drive; while the chair moves, a switch press must stop it. The
// controller is played here: each status on ~status (text) and ~path_status (with the stamp of
// the path it concerns), as the controller nodelet publishes them.
#include <wheelchair_msgs/PlanCertificate.h>

#include <actionlib_msgs/GoalStatus.h>
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>

#include <algorithm>
#include <string>
#include <vector>

#include "wait_for.h"

namespace {

using actionlib_msgs::GoalStatus;

class StaleEnd : public testing::Test {
 protected:
  void SetUp() override {
    announce_sub_ = nh_.subscribe<std_msgs::String>(
        "hmi/announce", 20,
        [this](const std_msgs::String::ConstPtr& m) { announced_.push_back(m->data); });
    stop_sub_ = nh_.subscribe<std_msgs::Empty>(
        "user_stop", 5, [this](const std_msgs::Empty::ConstPtr&) { ++stops_; });
    goal_pub_ = nh_.advertise<geometry_msgs::PoseStamped>("move_base_simple/goal", 1);
    cert_pub_ = nh_.advertise<wheelchair_msgs::PlanCertificate>("plan_certificate", 1);
    text_pub_ = nh_.advertise<std_msgs::String>("controller/status", 10);
    status_pub_ = nh_.advertise<GoalStatus>("controller/path_status", 10);
    switch_pub_ = nh_.advertise<std_msgs::Empty>("switch", 1);
    // The controller speaks on both topics; the HMI listens to one (it read ~status before).
    ASSERT_TRUE(waitFor([this] {
      return goal_pub_.getNumSubscribers() > 0 && cert_pub_.getNumSubscribers() > 0 &&
             status_pub_.getNumSubscribers() + text_pub_.getNumSubscribers() > 0 &&
             switch_pub_.getNumSubscribers() > 0 && !announced_.empty();
    })) << "the HMI is not up";
  }

  /// A goal as rviz sends it; returns its stamp.
  ros::Time sendGoal() {
    geometry_msgs::PoseStamped goal;
    goal.header.frame_id = "map";
    goal.header.stamp = ros::Time::now();
    goal.pose.position.x = 4.0;
    goal.pose.orientation.w = 1.0;
    goal_pub_.publish(goal);
    spinFor(0.2);
    return goal.header.stamp;
  }

  /// The planner's answer (success) and the /plan stamp it shares with the path.
  ros::Time planned() {
    wheelchair_msgs::PlanCertificate cert;
    cert.header.frame_id = "map";
    cert.header.stamp = ros::Time::now();
    cert.success = true;
    cert.length = 3.0;
    cert_pub_.publish(cert);
    spinFor(0.2);
    return cert.header.stamp;
  }

  /// The controller's status about the path stamped `path`.
  void controller(const std::string& text, uint8_t status, const ros::Time& path) {
    std_msgs::String s;
    s.data = text;
    text_pub_.publish(s);
    GoalStatus g;
    g.goal_id.stamp = path;
    g.status = status;
    g.text = text;
    status_pub_.publish(g);
    spinFor(0.3);
  }

  void spinFor(double seconds) {
    waitFor([] { return false; }, seconds);
  }

  bool saidStartingWith(const std::string& prefix, size_t from) const {
    return std::any_of(announced_.begin() + std::min(from, announced_.size()), announced_.end(),
                       [&](const std::string& s) { return s.rfind(prefix, 0) == 0; });
  }

  std::string said(size_t from) const {
    std::string all;
    for (size_t i = from; i < announced_.size(); ++i) all += "'" + announced_[i] + "' ";
    return all;
  }

  /// A press while the chair drives must stop it (and only then: a /user_stop).
  void expectPressStops(const std::string& when) {
    const int before = stops_;
    const size_t from = announced_.size();
    switch_pub_.publish(std_msgs::Empty());
    EXPECT_TRUE(waitFor([&] { return stops_ == before + 1; }, 3.0))
        << when << ": the press did not stop the chair; HMI said " << said(from);
    EXPECT_TRUE(saidStartingWith("Stopped.", from)) << when << ": " << said(from);
  }

  ros::NodeHandle nh_;
  ros::Subscriber announce_sub_, stop_sub_;
  ros::Publisher goal_pub_, cert_pub_, text_pub_, status_pub_, switch_pub_;
  std::vector<std::string> announced_;
  int stops_ = 0;
};

TEST_F(StaleEnd, OldGoalReachedAfterANewGoalNeitherArrivesNorKeepsThePressFromStopping) {
  sendGoal();
  const ros::Time path_a = planned();
  controller("aligning", GoalStatus::ACTIVE, path_a);
  controller("tracking", GoalStatus::ACTIVE, path_a);
  spinFor(0.5);  // the drive to A goes on; in its last moments the rider picks B in rviz
  const size_t from = announced_.size();
  sendGoal();
  controller("goal_reached", GoalStatus::SUCCEEDED, path_a);  // A's end, late
  const ros::Time path_b = planned();
  controller("aligning", GoalStatus::ACTIVE, path_b);
  EXPECT_FALSE(saidStartingWith("Arrived.", from)) << "A's end ended B's drive: " << said(from);
  expectPressStops("driving to B");
}

TEST_F(StaleEnd, OldAbortIsIgnoredButAnAbortOfTheNewGoalEndsTheDrive) {
  const ros::Time path_a = planned();
  controller("tracking", GoalStatus::ACTIVE, path_a);
  spinFor(0.5);
  const size_t from = announced_.size();
  sendGoal();
  controller("aborted: goal not reached within tolerance (P_l 0.060 m off)", GoalStatus::ABORTED,
             path_a);
  EXPECT_FALSE(saidStartingWith("Stopped:", from)) << "A's abort ended B's drive: " << said(from);
  // B's path comes during a safety hold: the controller refuses it, the rider must hear it.
  const ros::Time path_b = planned();
  controller("aborted: path ignored during safety stop (supervisor)", GoalStatus::ABORTED, path_b);
  EXPECT_TRUE(saidStartingWith("Stopped: aborted: path ignored during safety stop", from))
      << said(from);
  const int before = stops_;
  switch_pub_.publish(std_msgs::Empty());  // scanning again: a press selects, it sends no stop
  spinFor(0.5);
  EXPECT_EQ(stops_, before) << said(from);
}

TEST_F(StaleEnd, ChairMovingWhileScanningPutsTheHmiBackToDriving) {
  // Scanning (the previous test ended the drive). A path the HMI did not ask for (a replan on
  // a new map, a goal it missed) moves the chair: a press must stop it.
  spinFor(0.3);
  const size_t from = announced_.size();
  controller("tracking", GoalStatus::ACTIVE, ros::Time::now());
  EXPECT_TRUE(saidStartingWith("The chair is moving", from)) << said(from);
  expectPressStops("moving while scanning");
  // The stopped path's "tracking", late (sent before the stop reached the controller), does
  // not restart the drive.
  const size_t after_stop = announced_.size();
  controller("tracking", GoalStatus::ACTIVE, ros::Time::now() - ros::Duration(0.5));
  EXPECT_FALSE(saidStartingWith("The chair is moving", after_stop)) << said(after_stop);
}

TEST_F(StaleEnd, GoalRefusedWhileDrivingStopsTheChairAsTheRiderIsTold) {
  sendGoal();
  const ros::Time path_a = planned();
  controller("tracking", GoalStatus::ACTIVE, path_a);
  spinFor(0.5);
  const int before = stops_;
  const size_t from = announced_.size();
  sendGoal();  // rejected by the planner host without a path: the chair would drive on to A
  wheelchair_msgs::PlanCertificate cert;
  cert.header.stamp = ros::Time::now();
  cert.failure_reason = "goal rejected: frame 'odom', expected 'map'";
  cert_pub_.publish(cert);
  EXPECT_TRUE(waitFor([&] { return stops_ == before + 1; }, 3.0)) << said(from);
  EXPECT_TRUE(saidStartingWith("Cannot go there: goal rejected", from)) << said(from);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_hmi_stale_end");
  return RUN_ALL_TESTS();
}
