// The ROS face of the base driver: the chair's controller's commands and the supervisor's
// permits in through the process's drive channel (wheelchair_ros/drive_channel.h), CAN frames
// out through a transport; /odom, tf odom->base_link, /joint_states, diagnostics and a status
// out; e-stop in. /wheel_torques is only watched: a message from another node latches a stop.
#pragma once

#include <wheelchair_base_driver/base_driver_core.h>
#include <wheelchair_base_driver/base_driver_settings.h>
#include <wheelchair_can/emulated_motor_controller.h>
#include <wheelchair_can/simple_wheel_plant.h>
#include <wheelchair_can/transport.h>

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <std_msgs/Bool.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_msgs/WheelTorques.h>
#include <wheelchair_ros/drive_channel.h>

#include <memory>
#include <mutex>
#include <string>

namespace wheelchair_base_driver {

class BaseDriverNodelet : public nodelet::Nodelet {
 public:
  ~BaseDriverNodelet() override;

 private:
  void onInit() override;
  /// Every private parameter, the chair file's geometry and torque limit as their defaults.
  /// Throws wheelchair_core::ConfigError (the nodelet is then refused).
  BaseDriverSettings loadSettings();
  void startEmulatedController();
  /// The chair's own controller (drive channel).
  bool onCommand(const wheelchair_ros::DriveCommand& command);
  /// Any node's /wheel_torques: the chair's own (this process) are the controller's, for logs;
  /// another publisher's latch a stop.
  void onTorques(const ros::MessageEvent<wheelchair_msgs::WheelTorques const>& event);
  void onEstopTopic(const std_msgs::Bool::ConstPtr& msg);
  bool onEstopService(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  bool onClearEstopService(std_srvs::Trigger::Request& req, std_srvs::Trigger::Response& res);
  void onTimer(const ros::TimerEvent& event);
  void onWallTimer(const ros::WallTimerEvent& event);
  /// Tells the supervisor and the controller (drive channel) what changed, outside the lock.
  void reportEvents();
  void publishOdometry(const ros::Time& stamp);
  void publishStatus();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  std::mutex mutex_;  // guards the core and the emulated controller
  BaseDriverSettings settings_;
  std::shared_ptr<wheelchair_can::CanTransport> transport_;
  std::unique_ptr<BaseDriverCore> core_;
  // Stand-alone fake mode: a controller with a trivial plant on the same fake bus.
  std::shared_ptr<wheelchair_can::CanTransport> emulated_port_;
  std::unique_ptr<wheelchair_can::SimpleWheelPlant> emulated_plant_;
  std::unique_ptr<wheelchair_can::EmulatedMotorController> emulated_controller_;
  double last_plant_time_ = -1.0;

  ros::Subscriber torque_sub_, estop_sub_;
  ros::Publisher odom_pub_, joint_pub_, status_pub_;
  ros::ServiceServer estop_srv_, clear_srv_;
  ros::Timer timer_;
  ros::WallTimer wall_timer_;
  std::mutex report_mutex_;  // keeps the channel's reports in order
  std::shared_ptr<wheelchair_ros::DriveChannel> channel_;
  std::unique_ptr<wheelchair_ros::DriveChannel::Registration> registration_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_;
  std::unique_ptr<diagnostic_updater::Updater> diagnostics_;
  double last_odom_stamp_ = -1.0;
  double odom_period_ = 0.0;  ///< [s] least time between published odometries (0: every frame)
  double last_status_time_ = -1.0;
  DriverState last_logged_state_ = DriverState::kNoController;
};

}  // namespace wheelchair_base_driver
