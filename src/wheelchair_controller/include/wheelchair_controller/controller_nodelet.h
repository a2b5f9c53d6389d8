// ROS wrapper of PathTracker: /plan, tf map->base_link and /odom in; /wheel_torques out at a
// fixed rate, plus ~reference, ~tracking_error and ~status for rviz and tests.
#pragma once

#include <wheelchair_controller/path_tracker.h>

#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace wheelchair_controller {

class ControllerNodelet : public nodelet::Nodelet {
 public:
  void onInit() override;

 private:
  void onPath(const nav_msgs::Path::ConstPtr& msg);
  void onOdometry(const nav_msgs::Odometry::ConstPtr& msg);
  void onTimer(const ros::TimerEvent& event);
  std::optional<PoseMeasurement> lookupPose();
  void publish(const TrackerOutput& out, const ros::Time& now);

  std::mutex mutex_;
  std::unique_ptr<PathTracker> tracker_;
  wheelchair_description::ChairParams chair_;
  std::string map_frame_, base_frame_;
  WheelSpeedMeasurement wheels_;
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Subscriber path_sub_, odom_sub_;
  ros::Publisher torque_pub_, reference_pub_, error_pub_, status_pub_;
  ros::Timer timer_;
  std::string last_status_;
};

}  // namespace wheelchair_controller
