#include "drive_source.h"

#include <wheelchair_ros/conversions.h>

#include <cmath>

namespace wheelchair_display {
namespace {

/// [s] a controller status about a path stamped this much before the goal still answers it
/// (another process's clock); an older one belongs to an earlier drive.
constexpr double kStampTolerance = 0.1;
/// [m] the controller may abort "goal not reached within tolerance" a few mm off: still there.
constexpr double kArrivalRadius = 0.15;

bool near(const wheelchair_core::Pose2D& a, double x, double y) {
  return std::hypot(a.x - x, a.y - y) < 0.05;
}

}  // namespace

LegacyDriveSource::LegacyDriveSource(ros::NodeHandle& nh, DriveTracker& tracker,
                                     const std::vector<wheelchair_hmi::Place>& places)
    : tracker_(tracker), places_(places) {
  subs_.push_back(nh.subscribe("move_base_simple/goal", 5, &LegacyDriveSource::onGoal, this));
  subs_.push_back(nh.subscribe("plan", 2, &LegacyDriveSource::onPath, this));
  subs_.push_back(nh.subscribe("plan_certificate", 2, &LegacyDriveSource::onCertificate, this));
  subs_.push_back(
      nh.subscribe("controller/path_status", 10, &LegacyDriveSource::onPathStatus, this));
  subs_.push_back(nh.subscribe("user_stop", 5, &LegacyDriveSource::onUserStop, this));
  subs_.push_back(nh.subscribe("navigator/state", 5, &LegacyDriveSource::onNavigatorState, this));
}

void LegacyDriveSource::expectOwnGoal(const std::string& destination,
                                      const wheelchair_core::Pose2D& goal) {
  own_goal_ = std::make_pair(destination, goal);
}

std::string LegacyDriveSource::nameOf(const wheelchair_core::Pose2D& goal) const {
  if (own_goal_ && near(own_goal_->second, goal.x, goal.y)) return own_goal_->first;
  for (const auto& p : places_)
    if (near(goal, p.pose.x, p.pose.y)) return p.name;
  return "";
}

void LegacyDriveSource::onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  const wheelchair_core::Pose2D goal = wheelchair_ros::toPose2D(msg->pose);
  goal_stamp_ = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  tracker_.goal(nameOf(goal), goal, ros::Time::now().toSec());
  own_goal_.reset();
}

void LegacyDriveSource::onPath(const nav_msgs::Path::ConstPtr& msg) {
  if (msg->header.stamp + ros::Duration(kStampTolerance) < goal_stamp_) return;
  // The navigator's drive: an empty route is the navigator stopping the controller (a safety
  // stop, a wait, the end of the drive), no refusal; its state tells how the drive ends.
  if (msg->poses.empty() && !navigator_goal_id_.empty()) return;
  tracker_.route(wheelchair_ros::fromPathMsg(*msg), ros::Time::now().toSec());
}

void LegacyDriveSource::onCertificate(const wheelchair_msgs::PlanCertificate::ConstPtr& msg) {
  if (msg->header.stamp + ros::Duration(kStampTolerance) < goal_stamp_) return;
  // The navigator's drive: a refused route is the navigator's to answer (it may plan again, or
  // end the drive with its reason, which its state then tells).
  if (!navigator_goal_id_.empty()) return;
  if (!msg->success) {
    ROS_INFO("display: the planner refused the goal: %s", msg->failure_reason.c_str());
    tracker_.refused(ros::Time::now().toSec());
  }
}

void LegacyDriveSource::onUserStop(const std_msgs::Empty::ConstPtr&) {
  tracker_.riderStopped(ros::Time::now().toSec());
}

void LegacyDriveSource::onPathStatus(const actionlib_msgs::GoalStatus::ConstPtr& msg) {
  if (msg->goal_id.stamp + ros::Duration(kStampTolerance) < goal_stamp_) return;
  const double now = ros::Time::now().toSec();
  if (msg->status == actionlib_msgs::GoalStatus::SUCCEEDED) tracker_.arrived(now);
  // The navigator's drive: the controller giving up a route is the navigator's to answer (it
  // waits, plans again, or ends the drive: its state tells).
  if (msg->status == actionlib_msgs::GoalStatus::ABORTED && navigator_goal_id_.empty()) {
    ROS_INFO("display: the drive ended: %s", msg->text.c_str());
    tracker_.ended(now, kArrivalRadius);
  }
}

void LegacyDriveSource::onNavigatorState(const wheelchair_msgs::NavigatorState::ConstPtr& msg) {
  const double now = ros::Time::now().toSec();
  if (msg->active && msg->goal_id != navigator_goal_id_) {
    navigator_goal_id_ = msg->goal_id;
    const wheelchair_core::Pose2D goal = wheelchair_ros::toPose2D(msg->goal.pose);
    const auto& told = tracker_.goalPose();
    if (!(tracker_.driving() && told && near(*told, goal.x, goal.y))) {
      const std::string name = msg->place.empty() ? nameOf(goal) : msg->place;
      goal_stamp_ = msg->goal.header.stamp.isZero() ? ros::Time::now() : msg->goal.header.stamp;
      tracker_.goal(name, goal, now);
      own_goal_.reset();
    }
  }
  using wheelchair_msgs::NavigatorState;
  if (msg->active) {
    // Waiting for something in the way, or blocked: the navigator's words say why.
    const bool held_up =
        msg->state == NavigatorState::WAITING || msg->state == NavigatorState::BLOCKED;
    tracker_.heldUp(held_up ? msg->sentence : "");
  } else if (!navigator_goal_id_.empty()) {
    navigator_goal_id_.clear();
    // Idle, its sentence is how the drive ended (the one the HMI tells the rider).
    if (tracker_.driving()) tracker_.ended(now, kArrivalRadius, msg->sentence);
  }
}

}  // namespace wheelchair_display
