// Test helper: the navigator's `navigate` action played by the test (an actionlib server in
// the test node): it records the goals the HMI sends and their cancel requests, and answers with
// feedback and results as the navigator would.
#pragma once

#include <wheelchair_msgs/NavigateAction.h>

#include <actionlib/server/action_server.h>
#include <ros/ros.h>

#include <vector>

class FakeNavigator {
 public:
  using Server = actionlib::ActionServer<wheelchair_msgs::NavigateAction>;

  explicit FakeNavigator(ros::NodeHandle& nh)
      : server_(
            nh, "navigate", [this](Server::GoalHandle gh) { goals.push_back(gh); },
            [this](Server::GoalHandle gh) { cancels.push_back(gh.getGoalID().id); }, false) {
    server_.start();
    // The HMI's client sees a server by its status, which the server publishes from a timer of
    // this (test) thread's queue: spin a moment so that it connects before the first goal.
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(1.5);
    while (ros::ok() && ros::WallTime::now() < end) {
      ros::spinOnce();
      ros::WallDuration(0.01).sleep();
    }
  }

  /// Accepts goal `i` and says `sentence` about it (the navigator's feedback).
  void say(size_t i, const std::string& sentence,
           uint8_t state = wheelchair_msgs::NavigatorState::DRIVING) {
    if (goals[i].getGoalStatus().status == actionlib_msgs::GoalStatus::PENDING)
      goals[i].setAccepted();
    wheelchair_msgs::NavigateFeedback feedback;
    feedback.state.state = state;
    feedback.state.active = true;
    feedback.state.sentence = sentence;
    goals[i].publishFeedback(feedback);
  }

  /// Ends goal `i` with `reason` and its sentence.
  void end(size_t i, uint8_t reason, const std::string& sentence) {
    if (goals[i].getGoalStatus().status == actionlib_msgs::GoalStatus::PENDING)
      goals[i].setAccepted();
    wheelchair_msgs::NavigateResult result;
    result.reason = reason;
    result.sentence = sentence;
    if (reason == wheelchair_msgs::NavigateResult::REACHED)
      goals[i].setSucceeded(result, sentence);
    else
      goals[i].setAborted(result, sentence);
  }

  std::vector<Server::GoalHandle> goals;
  std::vector<std::string> cancels;

 private:
  Server server_;
};
