// ROS wrapper of PathTracker: /plan, tf map->base_link and /odom in; /wheel_torques out at a
// fixed rate, plus ~reference, ~tracking_error and ~status for rviz and tests. Stops (controlled)
// on /safety/stop (latched Bool), /user_stop (Empty) and kld/localized != "localized".
// A path's reference is built on a worker thread; the control step only swaps it in.
#pragma once

#include <wheelchair_controller/path_tracker.h>

#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <wheelchair_common/shared_tf.h>

#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace wheelchair_controller {

class ControllerNodelet : public nodelet::Nodelet {
 public:
  ~ControllerNodelet() override;
  void onInit() override;

 private:
  /// A path waiting for its reference to be built.
  struct PathRequest {
    std::vector<Pose2> poses;
    double initial_speed = 0.0;
    uint64_t sequence = 0, stop_count = 0;
  };
  void onPath(const nav_msgs::Path::ConstPtr& msg);
  void onSafetyStop(const std_msgs::Bool::ConstPtr& msg);
  void onUserStop(const std_msgs::Empty::ConstPtr& msg);
  void onLocalized(const std_msgs::String::ConstPtr& msg);
  void buildReferences();  ///< worker thread
  void onOdometry(const nav_msgs::Odometry::ConstPtr& msg);
  void onTimer(const ros::TimerEvent& event);
  std::optional<PoseMeasurement> lookupPose();
  void publish(const TrackerOutput& out, const ros::Time& now);

  std::mutex mutex_;
  std::unique_ptr<PathTracker> tracker_;
  wheelchair_description::ChairParams chair_;
  std::string map_frame_, base_frame_;
  WheelSpeedMeasurement wheels_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  ros::Subscriber path_sub_, odom_sub_, safety_sub_, user_stop_sub_, localized_sub_;
  ros::Publisher torque_pub_, reference_pub_, error_pub_, status_pub_;
  ros::Timer timer_;
  std::string last_status_;

  // Worker: builds the latest requested path's reference; mutex_ guards it too.
  std::condition_variable request_cv_;
  std::optional<PathRequest> request_;
  uint64_t path_sequence_ = 0;
  bool shutdown_ = false;
  std::thread worker_;
};

}  // namespace wheelchair_controller
