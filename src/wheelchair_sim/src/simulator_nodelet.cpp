// ROS face of the simulator: torques in, sensors and ground truth out, and it owns /clock.
// Torques come from /wheel_torques, or (~motor_bus = "udp" | "fake") from an emulated CAN motor
// controller that the real base driver talks to; the driver then publishes the odometry.
#include "sim_messages.h"

#include <wheelchair_can/emulated_motor_controller.h>
#include <wheelchair_can/fake_bus.h>
#include <wheelchair_can/udp_transport.h>
#include <wheelchair_description/chair_file.h>
#include <wheelchair_msgs/WheelTorques.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>
#include <wheelchair_sim/AddMovingObstacle.h>
#include <wheelchair_sim/AddObstacle.h>
#include <wheelchair_sim/EnableLaser.h>
#include <wheelchair_sim/MotorFault.h>
#include <wheelchair_sim/SetPose.h>
#include <wheelchair_sim/motor_plant_adapter.h>
#include <wheelchair_sim/simulated_chair.h>
#include <wheelchair_sim/simulator_settings.h>
#include <wheelchair_sim/world_loader.h>

#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/package.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Bool.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <pluginlib/class_list_macros.hpp>

#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <thread>

namespace wheelchair_sim {

namespace can = wheelchair_can;
namespace core = wheelchair_core;

/// [wall s] the loop may fall behind ~speed before it stops trying to catch up.
constexpr double kMaxLag = 0.02;

class SimulatorNodelet : public nodelet::Nodelet {
 public:
  ~SimulatorNodelet() override {
    running_ = false;
    if (loop_.joinable()) loop_.join();
  }

 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    try {
      settings_ = loadSettings(pnh);
      chair_sim_ =
          std::make_unique<SimulatedChair>(chair_, settings_.sim, loadWorld(settings_.world));
    } catch (const std::exception& e) {
      NODELET_FATAL("simulator cannot start: %s", e.what());
      throw;
    }
    const core::Pose2D& start = settings_.initial;
    if (!chair_sim_->reset(start)) {
      NODELET_FATAL("initial pose (%.2f, %.2f, %.2f) collides with %s", start.x, start.y, start.yaw,
                    settings_.world.c_str());
      throw std::runtime_error("initial pose collides");
    }
    try {
      for (const Disc& disc : obstaclesParameter(pnh))
        chair_sim_->simulator().obstacles().add(disc);  // throws on bad values
    } catch (const std::exception& e) {
      NODELET_FATAL("simulator cannot start: ~obstacles: %s", e.what());
      throw;
    }
    if (!settings_.motor_bus.empty()) startMotorController();

    clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("clock", 10);
    scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan", 5);
    if (chair_sim_->hasRearLaser())
      rear_scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("rear_scan", 5);
    if (motor_controller_) settings_.publish_odometry = false;  // the driver's, from our encoders
    if (settings_.publish_odometry) odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
    truth_pub_ = nh.advertise<nav_msgs::Odometry>("sim/ground_truth", 10);
    collision_pub_ = nh.advertise<std_msgs::Bool>("sim/collision", 1, true);
    trajectory_pub_ = nh.advertise<nav_msgs::Path>("sim/trajectory", 1, true);
    trajectory_.header.frame_id = settings_.map_frame;
    if (!motor_controller_)
      torque_sub_ = nh.subscribe("wheel_torques", 10, &SimulatorNodelet::onTorques, this);
    teleport_srv_ = nh.advertiseService("sim/teleport", &SimulatorNodelet::onTeleport, this);
    reset_srv_ = nh.advertiseService("sim/reset", &SimulatorNodelet::onReset, this);
    add_obstacle_srv_ =
        nh.advertiseService("sim/add_obstacle", &SimulatorNodelet::onAddObstacle, this);
    add_moving_obstacle_srv_ = nh.advertiseService("sim/add_moving_obstacle",
                                                   &SimulatorNodelet::onAddMovingObstacle, this);
    clear_obstacles_srv_ =
        nh.advertiseService("sim/clear_obstacles", &SimulatorNodelet::onClearObstacles, this);
    laser_srv_ = nh.advertiseService("sim/enable_laser", &SimulatorNodelet::onEnableLaser, this);
    if (motor_controller_)
      fault_srv_ = nh.advertiseService("sim/motor_fault", &SimulatorNodelet::onMotorFault, this);
    rear_laser_srv_ =
        nh.advertiseService("sim/enable_rear_laser", &SimulatorNodelet::onEnableRearLaser, this);
    tf_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    if (settings_.publish_laser_tf) {
      static_tf_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
      static_tf_->sendTransform(
          transformMessage(ros::Time(0), settings_.base_frame, settings_.laser_frame,
                           {chair_.laser_x, chair_.laser_y, chair_.laser_yaw}, chair_.laser_z));
      static_tf_->sendTransform(transformMessage(
          ros::Time(0), settings_.base_frame, settings_.rear_laser_frame,
          {chair_.rear_laser_x, chair_.rear_laser_y, chair_.rear_laser_yaw}, chair_.rear_laser_z));
    }
    publishCollision(false);
    NODELET_INFO("simulator: world %s, speed %.1f (0 = as fast as possible), step %.3f s",
                 settings_.world.c_str(), settings_.speed, settings_.step);
    running_ = true;
    loop_ = std::thread(&SimulatorNodelet::run, this);
  }

  /// Every private parameter over the files' values: the chair (chair_file) and sim.yaml
  /// (sim_config), both found at run time unless given. Throws wheelchair_core::ConfigError.
  SimulatorSettings loadSettings(const ros::NodeHandle& pnh) {
    chair_ = wheelchair_description::loadChairOf(pnh);
    SimulatorSettings defaults;
    wheelchair_ros::RosParameterSource(pnh).get("sim_config", defaults.sim_config);
    defaults.sim = loadSimParams(defaults.sim_config.empty()
                                     ? ros::package::getPath("wheelchair_sim") + "/config/sim.yaml"
                                     : defaults.sim_config);
    defaults.motor_controller.max_torque = chair_.max_wheel_torque;
    return wheelchair_ros::loadParameters(pnh, readSimulatorSettings, defaults);
  }

  /// The motor side of the CAN bus: on UDP (ports match base_driver's `_transport:=udp`) or on
  /// the named fake bus of this process (base_driver `_transport:=fake
  /// _emulate_controller:=false` in the same manager).
  void startMotorController() {
    motor_plant_ = std::make_unique<SimulatorMotorPlant>(chair_sim_->simulator());
    if (settings_.motor_bus == "udp") {
      // Frames are stamped in simulated time; only the simulation thread calls step().
      motor_transport_ =
          std::make_shared<can::UdpTransport>(static_cast<std::uint16_t>(settings_.udp_local_port),
                                              static_cast<std::uint16_t>(settings_.udp_remote_port),
                                              [this] { return chair_sim_->simulator().time(); });
    } else {  // "fake": the bus's clock is the driver's (ROS time)
      motor_transport_ = can::FakeBus::named(settings_.fake_bus)->connect("simulator");
    }
    motor_controller_ = std::make_unique<can::EmulatedMotorController>(
        settings_.motor_controller, *motor_transport_, *motor_plant_);
    NODELET_INFO("simulator: motor controller on %s, no /wheel_torques, no /odom",
                 motor_transport_->describe().c_str());
  }

  bool onAddObstacle(AddObstacle::Request& req, AddObstacle::Response& res) {
    Disc disc;
    disc.centre = {req.x, req.y};
    disc.radius = req.radius;
    disc.appear_time = req.appear_time;
    res.success = addDisc(disc, res.message);
    return true;
  }

  /// A person walking (or standing, then leaving): velocity and a vanish time.
  bool onAddMovingObstacle(AddMovingObstacle::Request& req, AddMovingObstacle::Response& res) {
    Disc disc;
    disc.centre = {req.x, req.y};
    disc.radius = req.radius;
    disc.appear_time = req.appear_time;
    disc.velocity = {req.vx, req.vy};
    disc.vanish_time = req.vanish_time == 0.0 ? INFINITY : req.vanish_time;
    res.success = addDisc(disc, res.message);
    return true;
  }

  /// Adds `disc` to the world; false with the reason in `message` when it is refused.
  bool addDisc(const Disc& disc, std::string& message) {
    std::lock_guard<std::mutex> lock(mutex_);
    try {
      chair_sim_->simulator().obstacles().add(disc);
    } catch (const std::invalid_argument& e) {
      message = e.what();
      return false;
    }
    message = "obstacle added";
    NODELET_INFO("obstacle r=%.2f m at (%.2f, %.2f) moving (%.2f, %.2f) m/s from t=%.2f to %.2f s",
                 disc.radius, disc.centre.x(), disc.centre.y(), disc.velocity.x(),
                 disc.velocity.y(), disc.appear_time, disc.vanish_time);
    return true;
  }

  bool onClearObstacles(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    chair_sim_->simulator().obstacles().clear();
    res.success = true;
    res.message = "obstacles cleared";
    return true;
  }

  /// Laser dropout on demand (false: no /scan at all until enabled again).
  bool onEnableLaser(EnableLaser::Request& req, EnableLaser::Response& res) {
    laser_on_ = req.enable;
    res.success = true;
    res.message = req.enable ? "laser on" : "laser silent";
    NODELET_WARN("%s", res.message.c_str());
    return true;
  }

  /// A single fault of the motor side, injected into the emulated motor controller.
  bool onMotorFault(MotorFault::Request& req, MotorFault::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    res.success = true;
    if (req.fault == "power_off" || req.fault == "power_on") {
      motor_controller_->setPowered(req.fault == "power_on");
    } else if (req.fault == "freeze_left_encoder" || req.fault == "freeze_right_encoder") {
      motor_controller_->freezeEncoders(req.fault == "freeze_left_encoder",
                                        req.fault == "freeze_right_encoder");
    } else if (req.fault == "thaw_encoders") {
      motor_controller_->freezeEncoders(false, false);
    } else if (req.fault == "overcurrent_left" || req.fault == "clear_faults") {
      motor_controller_->setInjectedFaults(
          req.fault == "clear_faults" ? 0 : wheelchair_can::protocol::kFaultOvercurrentLeft);
    } else {
      res.success = false;
    }
    res.message = res.success ? "motor fault: " + req.fault : "unknown fault '" + req.fault + "'";
    NODELET_WARN("%s", res.message.c_str());
    return true;
  }

  /// Rear laser dropout on demand (false: no /rear_scan at all until enabled again).
  bool onEnableRearLaser(EnableLaser::Request& req, EnableLaser::Response& res) {
    rear_laser_on_ = req.enable;
    res.success = true;
    res.message = req.enable ? "rear laser on" : "rear laser silent";
    NODELET_WARN("%s", res.message.c_str());
    return true;
  }

  void onTorques(const wheelchair_msgs::WheelTorques::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!std::isfinite(msg->left) || !std::isfinite(msg->right)) {
      NODELET_WARN_THROTTLE(1.0, "non-finite wheel torques (%f, %f) rejected: zero torque",
                            msg->left, msg->right);
      chair_sim_->simulator().applyWheelTorques(0.0, 0.0, msg->brake);
      last_torque_time_ = -1e9;
      return;
    }
    chair_sim_->simulator().applyWheelTorques(msg->right, msg->left, msg->brake);
    last_torque_time_ = chair_sim_->simulator().time();
    torques_stale_ = false;
  }

  bool onTeleport(SetPose::Request& req, SetPose::Response& res) {
    return movePose(req, res, false);
  }
  bool onReset(SetPose::Request& req, SetPose::Response& res) { return movePose(req, res, true); }

  bool movePose(const SetPose::Request& req, SetPose::Response& res, bool reset_odometry) {
    std::lock_guard<std::mutex> lock(mutex_);
    const core::Pose2D pose{req.x, req.y, req.yaw};
    res.success = reset_odometry ? chair_sim_->reset(pose) : chair_sim_->teleport(pose);
    res.message = res.success ? "moved" : "pose collides or is not finite: chair not moved";
    if (res.success) {
      if (reset_odometry) trajectory_.poses.clear();  // a new run; a kidnapping stays visible
      chair_sim_->simulator().applyWheelTorques(0.0, 0.0, false);
      publishCollision(false);
    }
    return true;
  }

  /// The true path for rviz and reports (a point every kTrajectoryStep), latched.
  void extendTrajectory(const ros::Time& now, const core::Pose2D& pose) {
    constexpr double kTrajectoryStep = 0.05;  // [m]
    if (!trajectory_.poses.empty()) {
      const auto& last = trajectory_.poses.back().pose.position;
      if (std::hypot(pose.x - last.x, pose.y - last.y) < kTrajectoryStep) return;
    }
    geometry_msgs::PoseStamped p;
    p.header.stamp = now;
    p.header.frame_id = settings_.map_frame;
    p.pose = wheelchair_ros::toPoseMsg(pose);
    trajectory_.header.stamp = now;
    trajectory_.poses.push_back(p);
    trajectory_pub_.publish(trajectory_);
  }

  void publishCollision(bool collided) {
    std_msgs::Bool msg;
    msg.data = collided;
    collision_pub_.publish(msg);
  }

  /// Zero torque when no command arrived for torque_timeout simulated seconds.
  void guardStaleTorques() {
    if (chair_sim_->simulator().time() - last_torque_time_ <= settings_.torque_timeout) return;
    if (!torques_stale_) {
      NODELET_WARN("no /wheel_torques for %.2f s of simulated time: zero torque",
                   settings_.torque_timeout);
      torques_stale_ = true;
    }
    chair_sim_->simulator().applyWheelTorques(0.0, 0.0, false);
  }

  void run() {
    ros::WallTime wall_start = ros::WallTime::now();
    double sim_elapsed = 0.0;
    while (running_ && ros::ok()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (motor_controller_) {
          motor_controller_->step(chair_sim_->simulator().time());  // its watchdogs brake
        } else {
          guardStaleTorques();
        }
        const SensorOutputs out = chair_sim_->advance(settings_.step);
        publish(out);
      }
      sim_elapsed += settings_.step;
      if (settings_.speed > 0.0) {
        const ros::WallTime due = wall_start + ros::WallDuration(sim_elapsed / settings_.speed);
        const ros::WallTime now = ros::WallTime::now();
        const ros::WallDuration wait = due - now;
        if (wait > ros::WallDuration(0)) {
          wait.sleep();
        } else if (wait < ros::WallDuration(-kMaxLag)) {
          // Behind after a stall (loaded machine): do not race to catch up — a burst of
          // simulated time would starve every node of CPU; simulated time runs slower instead.
          wall_start = now - ros::WallDuration(sim_elapsed / settings_.speed);
        }
      } else {
        std::this_thread::yield();
      }
    }
  }

  void publish(const SensorOutputs& out) {
    const Simulator& sim = chair_sim_->simulator();
    const ros::Time now(sim.time());
    rosgraph_msgs::Clock clock;
    clock.clock = now;
    clock_pub_.publish(clock);
    if (out.collision_started) {
      const core::Pose2D p = sim.pose();
      NODELET_ERROR("COLLISION at (%.2f, %.2f, %.2f): chair stopped and held", p.x, p.y, p.yaw);
      publishCollision(true);
    }
    if (out.scan && laser_on_)
      scan_pub_.publish(scanMessage(*out.scan, settings_.laser_frame, settings_.sim.laser_rate));
    if (out.rear_scan && rear_laser_on_)
      rear_scan_pub_.publish(
          scanMessage(*out.rear_scan, settings_.rear_laser_frame, settings_.sim.laser_rate));
    if (!out.odometry_due) return;
    const std::string& base = settings_.base_frame;
    truth_pub_.publish(odometryMessage(now, settings_.map_frame, base, sim.pose(), sim.velocity()));
    extendTrajectory(now, sim.pose());
    if (!settings_.publish_odometry) return;
    const WheelOdometry& odo = chair_sim_->odometry();
    odom_pub_.publish(odometryMessage(now, settings_.odom_frame, base, odo.pose(), odo.velocity()));
    tf_->sendTransform(transformMessage(now, settings_.odom_frame, base, odo.pose()));
  }

  SimulatorSettings settings_;
  wheelchair_description::ChairParams chair_;
  std::unique_ptr<SimulatedChair> chair_sim_;
  std::unique_ptr<SimulatorMotorPlant> motor_plant_;
  std::shared_ptr<can::CanTransport> motor_transport_;
  std::unique_ptr<can::EmulatedMotorController> motor_controller_;
  double last_torque_time_ = -1e9;
  bool torques_stale_ = true;
  std::mutex mutex_;
  std::atomic<bool> running_{false};
  std::atomic<bool> laser_on_{true}, rear_laser_on_{true};
  std::thread loop_;
  ros::Publisher clock_pub_, scan_pub_, rear_scan_pub_, odom_pub_, truth_pub_, collision_pub_,
      trajectory_pub_;
  nav_msgs::Path trajectory_;
  ros::Subscriber torque_sub_;
  ros::ServiceServer teleport_srv_, reset_srv_, add_obstacle_srv_, add_moving_obstacle_srv_,
      clear_obstacles_srv_, laser_srv_, fault_srv_, rear_laser_srv_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_tf_;
};

}  // namespace wheelchair_sim

PLUGINLIB_EXPORT_CLASS(wheelchair_sim::SimulatorNodelet, nodelet::Nodelet)
