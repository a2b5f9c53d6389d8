// rostest: the controller nodelet (loaded into this process, so that the test can act as the
// safety supervisor through the drive channel) tracks a path (tf map->base_link and /odom fed
// here), then gets a fault (~fault: nan_path | stale_pose | pose_jump | zero_length_path |
// safety_stop | user_stop | localization_lost) and must command zero torque + brake and report
// "aborted: <reason>" on ~status; after the stop, it resumes only as specified. ~path_status
// says the same and names the path it concerns (the stamp of the /plan it answers). The
// supervisor's hold comes through the drive channel only: /safety/stop false from any node and a
// re-published /plan do not undo it.
#include <actionlib_msgs/GoalStatus.h>
#include <geometry_msgs/TransformStamped.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <nodelet/loader.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_msgs/WheelTorques.h>
#include <wheelchair_ros/drive_channel.h>

#include <atomic>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>
#include <string>

namespace {

/// 3 m straight ahead; a NaN at index nan_at; spacing 0: every pose at the origin.
nav_msgs::Path straightPath(int nan_at = -1, double spacing = 0.05) {
  nav_msgs::Path path;
  path.header.frame_id = "map";
  path.header.stamp = ros::Time::now();
  for (int i = 0; i <= 60; ++i) {
    geometry_msgs::PoseStamped p;
    p.header = path.header;
    p.pose.position.x = (i == nan_at) ? NAN : spacing * i;
    p.pose.orientation.w = 1.0;
    path.poses.push_back(p);
  }
  return path;
}

bool waitFor(const std::function<bool()>& condition, double timeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && ros::WallTime::now() < end) {
    if (condition()) return true;
    ros::WallDuration(0.01).sleep();
  }
  return condition();
}

}  // namespace

/// What each fault must produce on ~status after "aborted: ".
const std::map<std::string, std::string> kExpectedReason = {
    {"nan_path", "non-finite"},
    {"stale_pose", "stale pose"},
    {"pose_jump", "pose jump"},
    {"zero_length_path", "zero-length"},
    {"safety_stop", "safety stop: the laser scanner is silent"},
    {"user_stop", "user stop"},
    {"localization_lost", "localization lost: test"}};

TEST(ControllerNodelet, FaultEndsInZeroTorqueAndBrake) {
  ros::NodeHandle nh, pnh("~");
  const std::string fault = pnh.param<std::string>("fault", "nan_path");
  ASSERT_EQ(kExpectedReason.count(fault), 1u) << "unknown fault " << fault;
  wheelchair_msgs::WheelTorques last;
  std::atomic<int> count{0};
  std::string status;
  ros::Subscriber torque_sub = nh.subscribe<wheelchair_msgs::WheelTorques>(
      "wheel_torques", 10, [&](const wheelchair_msgs::WheelTorques::ConstPtr& m) {
        last = *m;
        ++count;
      });
  ros::Subscriber status_sub = nh.subscribe<std_msgs::String>(
      "controller/status", 10, [&](const std_msgs::String::ConstPtr& m) { status = m->data; });
  actionlib_msgs::GoalStatus path_status;
  std::mutex path_status_mutex;
  ros::Subscriber path_status_sub = nh.subscribe<actionlib_msgs::GoalStatus>(
      "controller/path_status", 10, [&](const actionlib_msgs::GoalStatus::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(path_status_mutex);
        path_status = *m;
      });
  // ~path_status reached `code` about the path stamped `stamp`, with ~status's text.
  const auto path_status_is = [&](uint8_t code, const ros::Time& stamp) {
    std::lock_guard<std::mutex> lock(path_status_mutex);
    return path_status.status == code && path_status.goal_id.stamp == stamp &&
           path_status.text == status;
  };
  ros::Publisher path_pub = nh.advertise<nav_msgs::Path>("plan", 1, true);
  ros::Publisher odom_pub = nh.advertise<nav_msgs::Odometry>("odom", 10);
  ros::Publisher safety_pub = nh.advertise<std_msgs::Bool>("safety/stop", 1, true);
  ros::Publisher user_stop_pub = nh.advertise<std_msgs::Empty>("user_stop", 1);
  ros::Publisher localized_pub =
      nh.advertise<wheelchair_msgs::LocalizationStatus>("localization/status", 1, true);
  tf2_ros::TransformBroadcaster tf;
  std::atomic<bool> publish_pose{true};
  std::atomic<double> pose_x{0.0};
  // The chair stands still at the origin (or pose_x): tf and /odom at 50 Hz.
  ros::Timer feed = nh.createTimer(ros::Duration(0.02), [&](const ros::TimerEvent&) {
    const ros::Time now = ros::Time::now();
    if (publish_pose) {
      geometry_msgs::TransformStamped t;
      t.header.stamp = now;
      t.header.frame_id = "map";
      t.child_frame_id = "base_link";
      t.transform.translation.x = pose_x;
      t.transform.rotation.w = 1.0;
      tf.sendTransform(t);
    }
    nav_msgs::Odometry odom;
    odom.header.stamp = now;
    odom.pose.pose.orientation.w = 1.0;
    odom_pub.publish(odom);
  });
  ros::AsyncSpinner spinner(2);
  spinner.start();
  const auto tracking = [&] { return !last.brake && std::abs(last.left) > 1e-3; };
  const auto stopped = [&] { return last.brake && last.left == 0.0 && last.right == 0.0; };

  ASSERT_TRUE(waitFor([&] { return count > 10; }, 20.0)) << "no /wheel_torques";
  EXPECT_TRUE(last.brake) << "idle controller holds the brake";
  nav_msgs::Path path = straightPath();
  path_pub.publish(path);
  ASSERT_TRUE(waitFor(tracking, 10.0))
      << "the controller does not start tracking; status: " << status;
  EXPECT_TRUE(waitFor(
      [&] { return path_status_is(actionlib_msgs::GoalStatus::ACTIVE, path.header.stamp); }, 2.0))
      << "~path_status while tracking; status: " << status;

  if (fault == "nan_path") {
    ros::WallDuration(0.05).sleep();  // a stamp of its own
    path = straightPath(30);
    path_pub.publish(path);
  } else if (fault == "stale_pose") {
    publish_pose = false;
  } else if (fault == "pose_jump") {
    pose_x = 1.0;
  } else if (fault == "zero_length_path") {
    ros::WallDuration(0.05).sleep();
    path = straightPath(-1, 0.0);
    path_pub.publish(path);
  } else if (fault == "safety_stop") {
    wheelchair_ros::SafetyHold hold;  // what the supervisor of this process says
    hold.stop = true;
    hold.sentence = "the laser scanner is silent";
    ASSERT_TRUE(wheelchair_ros::driveChannel()->hold(hold));
  } else if (fault == "user_stop") {
    user_stop_pub.publish(std_msgs::Empty());
  } else if (fault == "localization_lost") {
    wheelchair_msgs::LocalizationStatus s;
    s.state = wheelchair_msgs::LocalizationStatus::MISFIT;
    s.localized = false;
    s.detail = "test";
    localized_pub.publish(s);
  }
  EXPECT_TRUE(waitFor(stopped, 6.0)) << "status: " << status;
  EXPECT_TRUE(waitFor([&] { return status.rfind("aborted", 0) == 0; }, 1.0)) << status;
  EXPECT_NE(status.find(kExpectedReason.at(fault)), std::string::npos) << status;
  // The abort answers the path in effect: the refused one, or the one driven when it stopped.
  EXPECT_TRUE(waitFor(
      [&] { return path_status_is(actionlib_msgs::GoalStatus::ABORTED, path.header.stamp); }, 1.0))
      << "~path_status after the fault; status: " << status;
  // It stays stopped.
  ros::WallDuration(0.5).sleep();
  EXPECT_TRUE(stopped()) << status;

  // Resuming: a held stop (supervisor, localization) ignores paths until it is cleared; every
  // other stop resumes on the next valid path.
  pose_x = 0.0;
  publish_pose = true;
  const bool held = fault == "safety_stop" || fault == "localization_lost";
  if (held) {
    path = straightPath();
    path_pub.publish(path);
    ros::WallDuration(1.0).sleep();
    EXPECT_TRUE(stopped()) << "a path during a held stop must not resume; status: " << status;
    // The rider must hear that this (newer) path was refused: the abort now answers it.
    EXPECT_TRUE(path_status_is(actionlib_msgs::GoalStatus::ABORTED, path.header.stamp))
        << "~path_status of a path refused during a hold; status: " << status;
    if (fault == "safety_stop") {
      // The issue: another node published /safety/stop false and re-published the last /plan:
      // the chair drove 1.12 m. Neither is the supervisor's word.
      std_msgs::Bool foreign_clear;
      foreign_clear.data = false;
      safety_pub.publish(foreign_clear);
      ros::WallDuration(0.3).sleep();
      path_pub.publish(path);
      ros::WallDuration(1.0).sleep();
      EXPECT_TRUE(stopped()) << "a foreign /safety/stop false and a re-published plan resumed; "
                             << "status: " << status;
      wheelchair_ros::driveChannel()->hold(wheelchair_ros::SafetyHold());  // the supervisor's
    }
    wheelchair_msgs::LocalizationStatus localized;
    localized.state = wheelchair_msgs::LocalizationStatus::LOCALIZED;
    localized.localized = true;
    localized_pub.publish(localized);
    ros::WallDuration(1.0).sleep();
    EXPECT_TRUE(stopped()) << "clearing alone must not resume; status: " << status;
  }
  path = straightPath();
  path_pub.publish(path);
  EXPECT_TRUE(waitFor(tracking, 10.0))
      << "a new path after the stop must resume; status: " << status;
  EXPECT_TRUE(waitFor(
      [&] { return path_status_is(actionlib_msgs::GoalStatus::ACTIVE, path.header.stamp); }, 2.0))
      << "~path_status after resuming; status: " << status;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "controller_fault_rostest");
  nodelet::Loader loader(false);  // the controller, with the .test file's /controller parameters
  if (!loader.load("/controller", "wheelchair_controller/ControllerNodelet", {}, {})) return 1;
  const int result = RUN_ALL_TESTS();
  loader.unload("/controller");
  return result;
}
