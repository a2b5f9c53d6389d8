// ROS wrapper of PathTracker: /plan, tf map->base_link and /odom in; wheel torques out at a
// fixed rate to the base driver through the process's drive channel (wheelchair_ros/
// drive_channel.h: stamped, sequence-numbered; the only torque input of the driver), a copy on
// /wheel_torques for logs (and the simulator's direct mode), plus ~reference, ~tracking_error and
// ~status for rviz and tests. Stops (controlled) on the supervisor's hold (drive channel: held
// until it lifts it, i.e. the rider's release; /safety/stop is only its output), the driver's
// latched stop (drive channel), a hang in its own control steps (a shorter pause: brake, then
// on from rest; PathTracker::stepsPaused), /user_stop (Empty) and
// /localization/status (wheelchair_msgs/LocalizationStatus) not `localized`.
// A path's reference is built on a worker thread; the control step only swaps it in.
// ~path_status (actionlib_msgs/GoalStatus, latched) says the same as ~status and which path it
// concerns (goal_id.stamp = that /plan's header.stamp): an end status of an older path is not
// the answer to a newer goal (the HMI relies on it). status: PENDING idle, ACTIVE aligning /
// tracking / rotating_to_goal, PREEMPTING stopping, SUCCEEDED goal_reached, ABORTED aborted.
#pragma once

#include <wheelchair_controller/path_tracker.h>

#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <wheelchair_ros/shared_tf.h>

#include <actionlib_msgs/GoalStatus.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_ros/drive_channel.h>
#include <wheelchair_ros/expected_publisher.h>

#include <atomic>
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
    std::vector<Pose2D> poses;
    double initial_speed = 0.0;
    uint64_t sequence = 0, stop_count = 0;
    ros::Time stamp;  ///< the /plan's header.stamp
  };
  /// The newest path whose fate is not yet known: swapped in, refused, or dropped by a stop.
  struct PendingPath {
    uint64_t sequence = 0, stop_count = 0;
    ros::Time stamp;
  };
  void onPath(const nav_msgs::Path::ConstPtr& msg);
  /// The supervisor's verdict (drive channel): a hold while it says stop.
  void onHold(const wheelchair_ros::SafetyHold& hold);
  /// The driver's state (drive channel): a latched stop ends the drive.
  void onDriverReport(const wheelchair_ros::DriverReport& report);
  void onSpeedLimit(const ros::MessageEvent<std_msgs::Float64 const>& event);
  void onUserStop(const std_msgs::Empty::ConstPtr& msg);
  void onLocalizationStatus(const wheelchair_msgs::LocalizationStatus::ConstPtr& msg);
  void buildReferences();  ///< worker thread
  void onOdometry(const nav_msgs::Odometry::ConstPtr& msg);
  void onTimer(const ros::TimerEvent& event);
  std::optional<PoseMeasurement> lookupPose();
  /// Publishes the step's topics; returns the command for the driver (submitted unlocked).
  wheelchair_ros::DriveCommand publish(const TrackerOutput& out, const ros::Time& now);
  void publishStatus(const TrackerOutput& out);
  /// The pending path is decided (swapped in, refused, or dropped): the status now concerns it.
  void settlePending();

  std::mutex mutex_;
  std::unique_ptr<PathTracker> tracker_;
  wheelchair_description::ChairParams chair_;
  std::string map_frame_, base_frame_;
  WheelSpeedMeasurement wheels_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  ros::Subscriber path_sub_, odom_sub_, user_stop_sub_, localization_sub_;
  ros::Subscriber speed_limit_sub_;
  std::unique_ptr<wheelchair_ros::ExpectedPublisher> speed_limit_guard_;
  ros::Publisher torque_pub_, reference_pub_, error_pub_, status_pub_, path_status_pub_;
  ros::Timer timer_;
  std::string last_status_, last_path_status_;
  ros::Time status_path_stamp_, last_path_stamp_;  ///< the path the tracker's state concerns
  std::optional<PendingPath> pending_;
  std::shared_ptr<wheelchair_ros::DriveChannel> channel_;
  std::unique_ptr<wheelchair_ros::DriveChannel::Registration> registration_;
  std::optional<std::string> safety_hold_;  ///< the supervisor's hold in effect (its sentence)
  std::uint64_t command_sequence_ = 0;
  double gap_timeout_ = 0.1, wall_gap_timeout_ = 0.5;
  std::atomic<int64_t>* cpu_ = nullptr;  ///< this nodelet's callback CPU (callback_cpu.h)
  std::atomic<int64_t>* references_cpu_ = nullptr;  ///< the worker's (preparePath)
  ros::Time last_step_;
  ros::WallTime last_wall_step_;

  // Worker: builds the latest requested path's reference; mutex_ guards it too.
  std::condition_variable request_cv_;
  std::optional<PathRequest> request_;
  uint64_t path_sequence_ = 0;
  bool shutdown_ = false;
  std::thread worker_;
};

}  // namespace wheelchair_controller
