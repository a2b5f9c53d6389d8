// ROS face of the simulator: torques in, sensors and ground truth out, and it owns /clock.
// Torques come from /wheel_torques, or (~motor_bus = "udp") from an emulated CAN motor
// controller that the real base driver talks to; the driver then publishes the odometry.
#include <wheelchair_sim/AddObstacle.h>
#include <wheelchair_sim/EnableLaser.h>
#include <wheelchair_sim/SetPose.h>
#include <wheelchair_sim/motor_plant_adapter.h>
#include <wheelchair_sim/simulated_chair.h>
#include <wheelchair_sim/world_loader.h>

#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>
#include <wheelchair_base_driver/emulated_motor_controller.h>
#include <wheelchair_base_driver/udp_transport.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description/package_paths.h>
#include <wheelchair_msgs/WheelTorques.h>
#include <pluginlib/class_list_macros.hpp>

#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <thread>

namespace wheelchair_sim {

namespace {

geometry_msgs::Quaternion yawToQuaternion(double yaw) {
  geometry_msgs::Quaternion q;
  q.z = std::sin(0.5 * yaw);
  q.w = std::cos(0.5 * yaw);
  return q;
}

nav_msgs::Odometry odometryMessage(const ros::Time& stamp, const std::string& frame,
                                   const Eigen::Vector3d& pose, const Eigen::Vector2d& vel) {
  nav_msgs::Odometry m;
  m.header.stamp = stamp;
  m.header.frame_id = frame;
  m.child_frame_id = "base_link";
  m.pose.pose.position.x = pose.x();
  m.pose.pose.position.y = pose.y();
  m.pose.pose.orientation = yawToQuaternion(pose.z());
  m.twist.twist.linear.x = vel(0);
  m.twist.twist.angular.z = vel(1);
  return m;
}

geometry_msgs::TransformStamped transformMessage(const ros::Time& stamp, const std::string& parent,
                                                 const std::string& child, double x, double y,
                                                 double z, double yaw) {
  geometry_msgs::TransformStamped t;
  t.header.stamp = stamp;
  t.header.frame_id = parent;
  t.child_frame_id = child;
  t.transform.translation.x = x;
  t.transform.translation.y = y;
  t.transform.translation.z = z;
  t.transform.rotation = yawToQuaternion(yaw);
  return t;
}

sensor_msgs::LaserScan scanMessage(const ros::Time& stamp, const Scan& scan, double rate) {
  sensor_msgs::LaserScan m;
  m.header.stamp = stamp;
  m.header.frame_id = "laser";
  m.angle_min = scan.angle_min;
  m.angle_max = scan.angleMax();
  m.angle_increment = scan.angle_increment;
  m.time_increment = 0.0;  // all beams at the stamp
  m.scan_time = 1.0 / rate;
  m.range_min = scan.range_min;
  m.range_max = scan.range_max;
  m.ranges = scan.ranges;
  return m;
}

}  // namespace

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
    const std::string world_path = pnh.param<std::string>("world", "");
    const std::string chair_path =
        pnh.param<std::string>("chair_config", wheelchair_description::chairParamsPathFromRos());
    const std::string sim_path = pnh.param<std::string>(
        "sim_config", wheelchair_description::packageFile("wheelchair_sim", "config/sim.yaml",
                                                          defaultSimParamsPath()));
    pnh.param("speed", speed_, 1.0);
    pnh.param("step", step_, 0.005);
    pnh.param("torque_timeout", torque_timeout_, 0.5);
    pnh.param("publish_odometry", publish_odometry_, true);
    const bool publish_laser_tf = pnh.param("publish_laser_tf", false);
    std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world;
    try {
      chair_ = wheelchair_description::loadChairParams(chair_path);
      params_ = loadSimParams(sim_path);
      forEachParam(params_, [&](const char* name, auto& value) { pnh.param(name, value, value); });
      validate(params_);
      if (world_path.empty()) throw std::runtime_error("parameter ~world (map YAML) is not set");
      if (!(step_ > 0.0) || !(speed_ >= 0.0))
        throw std::runtime_error("need ~step > 0, ~speed >= 0");
      world = loadWorld(world_path);
      chair_sim_ = std::make_unique<SimulatedChair>(chair_, params_, world);
    } catch (const std::exception& e) {
      NODELET_FATAL("simulator cannot start: %s", e.what());
      throw;
    }
    const double x = pnh.param("initial_x", 0.0), y = pnh.param("initial_y", 0.0);
    const double yaw = pnh.param("initial_yaw", 0.0);
    if (!chair_sim_->reset(x, y, yaw)) {
      NODELET_FATAL("initial pose (%.2f, %.2f, %.2f) collides with %s", x, y, yaw,
                    world_path.c_str());
      throw std::runtime_error("initial pose collides");
    }
    try {
      loadObstacles(pnh);
    } catch (const std::exception& e) {
      NODELET_FATAL("simulator cannot start: ~obstacles: %s", e.what());
      throw;
    }
    const std::string motor_bus = pnh.param<std::string>("motor_bus", "");
    if (motor_bus == "udp") {
      startMotorController(pnh);
    } else if (!motor_bus.empty()) {
      NODELET_FATAL("unknown ~motor_bus '%s' (\"\" = /wheel_torques, \"udp\")", motor_bus.c_str());
      throw std::runtime_error("unknown ~motor_bus");
    }

    clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("clock", 10);
    scan_pub_ = nh.advertise<sensor_msgs::LaserScan>("scan", 5);
    if (motor_controller_) publish_odometry_ = false;  // the base driver's, from our encoders
    if (publish_odometry_) odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
    truth_pub_ = nh.advertise<nav_msgs::Odometry>("sim/ground_truth", 10);
    collision_pub_ = nh.advertise<std_msgs::Bool>("sim/collision", 1, true);
    trajectory_pub_ = nh.advertise<nav_msgs::Path>("sim/trajectory", 1, true);
    trajectory_.header.frame_id = "map";
    if (!motor_controller_)
      torque_sub_ = nh.subscribe("wheel_torques", 10, &SimulatorNodelet::onTorques, this);
    teleport_srv_ = nh.advertiseService("sim/teleport", &SimulatorNodelet::onTeleport, this);
    reset_srv_ = nh.advertiseService("sim/reset", &SimulatorNodelet::onReset, this);
    add_obstacle_srv_ =
        nh.advertiseService("sim/add_obstacle", &SimulatorNodelet::onAddObstacle, this);
    clear_obstacles_srv_ =
        nh.advertiseService("sim/clear_obstacles", &SimulatorNodelet::onClearObstacles, this);
    laser_srv_ = nh.advertiseService("sim/enable_laser", &SimulatorNodelet::onEnableLaser, this);
    tf_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    if (publish_laser_tf) {
      static_tf_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
      static_tf_->sendTransform(transformMessage(ros::Time(0), "base_link", "laser", chair_.laser_x,
                                                 chair_.laser_y, chair_.laser_z, chair_.laser_yaw));
    }
    publishCollision(false);
    NODELET_INFO("simulator: world %s, speed %.1f (0 = as fast as possible), step %.3f s",
                 world_path.c_str(), speed_, step_);
    running_ = true;
    loop_ = std::thread(&SimulatorNodelet::run, this);
  }

  /// The motor side of the CAN bus on UDP (ports match base_driver's `_transport:=udp`).
  void startMotorController(ros::NodeHandle& pnh) {
    const int local = pnh.param("udp_local_port", 47111);
    const int remote = pnh.param("udp_remote_port", 47110);
    if (local < 0 || local > 65535 || remote < 0 || remote > 65535)
      throw std::runtime_error("~udp_local_port / ~udp_remote_port out of range");
    wheelchair_base_driver::EmulatedControllerConfig config;
    config.counts_per_rev = pnh.param("counts_per_rev", config.counts_per_rev);
    config.max_torque = chair_.max_wheel_torque;
    motor_plant_ = std::make_unique<SimulatorMotorPlant>(chair_sim_->simulator());
    // Frames are stamped in simulated time; only the simulation thread calls step().
    motor_transport_ = std::make_unique<wheelchair_base_driver::UdpTransport>(
        local, remote, [this] { return chair_sim_->simulator().time(); });
    motor_controller_ = std::make_unique<wheelchair_base_driver::EmulatedMotorController>(
        config, *motor_transport_, *motor_plant_);
    NODELET_INFO("simulator: motor controller on %s, no /wheel_torques, no /odom",
                 motor_transport_->describe().c_str());
  }

  /// ~obstacles: [{x, y, radius, appear_time}, ...] (radius default 0.15, time default 0).
  void loadObstacles(ros::NodeHandle& pnh) {
    XmlRpc::XmlRpcValue list;
    if (!pnh.getParam("obstacles", list)) return;
    if (list.getType() != XmlRpc::XmlRpcValue::TypeArray)
      throw std::runtime_error("~obstacles must be a list of {x, y, radius, appear_time}");
    for (int i = 0; i < list.size(); ++i) {
      auto number = [&](const char* key, double fallback) {
        if (!list[i].hasMember(key)) return fallback;
        XmlRpc::XmlRpcValue& v = list[i][key];
        return v.getType() == XmlRpc::XmlRpcValue::TypeInt ? double(int(v)) : double(v);
      };
      Disc disc;
      disc.centre = {number("x", NAN), number("y", NAN)};
      disc.radius = number("radius", disc.radius);
      disc.appear_time = number("appear_time", 0.0);
      chair_sim_->simulator().obstacles().add(disc);  // throws on bad values
    }
  }

  bool onAddObstacle(AddObstacle::Request& req, AddObstacle::Response& res) {
    std::lock_guard<std::mutex> lock(mutex_);
    Disc disc;
    disc.centre = {req.x, req.y};
    disc.radius = req.radius;
    disc.appear_time = req.appear_time;
    try {
      chair_sim_->simulator().obstacles().add(disc);
    } catch (const std::invalid_argument& e) {
      res.success = false;
      res.message = e.what();
      return true;
    }
    res.success = true;
    res.message = "obstacle added";
    NODELET_INFO("obstacle r=%.2f m at (%.2f, %.2f) from t=%.2f s", req.radius, req.x, req.y,
                 req.appear_time);
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
    res.success = reset_odometry ? chair_sim_->reset(req.x, req.y, req.yaw)
                                 : chair_sim_->teleport(req.x, req.y, req.yaw);
    res.message = res.success ? "moved" : "pose collides or is not finite: chair not moved";
    if (res.success) {
      if (reset_odometry) trajectory_.poses.clear();  // a new run; a kidnapping stays visible
      chair_sim_->simulator().applyWheelTorques(0.0, 0.0, false);
      publishCollision(false);
    }
    return true;
  }

  /// The true path for rviz and reports (a point every kTrajectoryStep), latched.
  void extendTrajectory(const ros::Time& now, const Eigen::Vector3d& pose) {
    constexpr double kTrajectoryStep = 0.05;  // [m]
    if (!trajectory_.poses.empty()) {
      const auto& last = trajectory_.poses.back().pose.position;
      if (std::hypot(pose.x() - last.x, pose.y() - last.y) < kTrajectoryStep) return;
    }
    geometry_msgs::PoseStamped p;
    p.header.stamp = now;
    p.header.frame_id = "map";
    p.pose.position.x = pose.x();
    p.pose.position.y = pose.y();
    p.pose.orientation = yawToQuaternion(pose.z());
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
    if (chair_sim_->simulator().time() - last_torque_time_ <= torque_timeout_) return;
    if (!torques_stale_) {
      NODELET_WARN("no /wheel_torques for %.2f s of simulated time: zero torque", torque_timeout_);
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
        const SensorOutputs out = chair_sim_->advance(step_);
        publish(out);
      }
      sim_elapsed += step_;
      if (speed_ > 0.0) {
        const ros::WallTime due = wall_start + ros::WallDuration(sim_elapsed / speed_);
        const ros::WallTime now = ros::WallTime::now();
        const ros::WallDuration wait = due - now;
        if (wait > ros::WallDuration(0)) {
          wait.sleep();
        } else if (wait < ros::WallDuration(-kMaxLag)) {
          // Behind after a stall (loaded machine): do not race to catch up — a burst of
          // simulated time would starve every node of CPU; simulated time runs slower instead.
          wall_start = now - ros::WallDuration(sim_elapsed / speed_);
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
      const Eigen::Vector3d p = sim.pose();
      NODELET_ERROR("COLLISION at (%.2f, %.2f, %.2f): chair stopped and held", p.x(), p.y(), p.z());
      publishCollision(true);
    }
    if (out.scan && laser_on_) scan_pub_.publish(scanMessage(now, *out.scan, params_.laser_rate));
    if (!out.odometry_due) return;
    truth_pub_.publish(odometryMessage(now, "map", sim.pose(), sim.velocity()));
    extendTrajectory(now, sim.pose());
    if (!publish_odometry_) return;
    const WheelOdometry& odo = chair_sim_->odometry();
    odom_pub_.publish(odometryMessage(now, "odom", odo.pose(), odo.velocity()));
    tf_->sendTransform(transformMessage(now, "odom", "base_link", odo.pose().x(), odo.pose().y(),
                                        0.0, odo.pose().z()));
  }

  wheelchair_description::ChairParams chair_;
  SimParams params_;
  std::unique_ptr<SimulatedChair> chair_sim_;
  std::unique_ptr<SimulatorMotorPlant> motor_plant_;
  std::unique_ptr<wheelchair_base_driver::UdpTransport> motor_transport_;
  std::unique_ptr<wheelchair_base_driver::EmulatedMotorController> motor_controller_;
  double speed_ = 1.0, step_ = 0.005, torque_timeout_ = 0.5;
  bool publish_odometry_ = true;
  double last_torque_time_ = -1e9;
  bool torques_stale_ = true;
  std::mutex mutex_;
  std::atomic<bool> running_{false};
  std::atomic<bool> laser_on_{true};
  std::thread loop_;
  ros::Publisher clock_pub_, scan_pub_, odom_pub_, truth_pub_, collision_pub_, trajectory_pub_;
  nav_msgs::Path trajectory_;
  ros::Subscriber torque_sub_;
  ros::ServiceServer teleport_srv_, reset_srv_, add_obstacle_srv_, clear_obstacles_srv_, laser_srv_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_tf_;
};

}  // namespace wheelchair_sim

PLUGINLIB_EXPORT_CLASS(wheelchair_sim::SimulatorNodelet, nodelet::Nodelet)
