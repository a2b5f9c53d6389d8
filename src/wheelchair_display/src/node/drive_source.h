// Where the display learns about drives: the navigator's /navigator/state (every drive it owns,
// whoever started it: the HMI's switch through its action, this display, rviz), any goal on
// /move_base_simple/goal, the planner's /plan and /plan_certificate, the controller's path
// status, and any /user_stop. While the navigator owns a drive, it alone says how the drive
// goes on or ends: an empty route, a refused plan or the controller giving up are its to answer.
#pragma once

#include <wheelchair_display/drive_tracker.h>
#include <wheelchair_hmi/places.h>

#include <actionlib_msgs/GoalStatus.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_msgs/Empty.h>
#include <wheelchair_msgs/NavigatorState.h>
#include <wheelchair_msgs/PlanCertificate.h>

#include <optional>
#include <string>
#include <vector>

namespace wheelchair_display {

class LegacyDriveSource {
 public:
  LegacyDriveSource(ros::NodeHandle& nh, DriveTracker& tracker,
                    const std::vector<wheelchair_hmi::Place>& places);
  /// The display itself sends this goal for `destination` next (so it is told by name).
  void expectOwnGoal(const std::string& destination, const wheelchair_core::Pose2D& goal);

 private:
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void onPath(const nav_msgs::Path::ConstPtr& msg);
  void onCertificate(const wheelchair_msgs::PlanCertificate::ConstPtr& msg);
  void onPathStatus(const actionlib_msgs::GoalStatus::ConstPtr& msg);
  /// A stop from anyone (this display, another, the HMI's switch): the rider stopped the drive.
  void onUserStop(const std_msgs::Empty::ConstPtr&);
  /// The navigator's drive: a new one is a goal (if not already told by its goal topic); its end
  /// without an arrival verdict is an ended drive (arrived if the chair is at the goal).
  void onNavigatorState(const wheelchair_msgs::NavigatorState::ConstPtr& msg);
  /// The name of the place at `goal`, the display's own destination, or "" (a spot).
  std::string nameOf(const wheelchair_core::Pose2D& goal) const;

  DriveTracker& tracker_;
  const std::vector<wheelchair_hmi::Place>& places_;
  std::optional<std::pair<std::string, wheelchair_core::Pose2D>> own_goal_;
  ros::Time goal_stamp_;
  std::string navigator_goal_id_;  ///< the navigator's active drive, "" if none
  std::vector<ros::Subscriber> subs_;
};

}  // namespace wheelchair_display
