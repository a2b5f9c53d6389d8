// ROS layer of the safety supervisor: feeds it the localizer's estimate and status, tf
// map -> base_link, the laser (returns projected into the map), the map, the plan, the base
// driver's status and the rider's commands; publishes a latched stop flag and its reason.
#include <wheelchair_ros/conversions.h>
#include <wheelchair_safety/safety_supervisor.h>

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Empty.h>
#include <std_msgs/String.h>
#include <tf2/utils.h>
#include <tf2_ros/buffer.h>
#include <wheelchair_ros/shared_tf.h>
#include <pluginlib/class_list_macros.hpp>

#include <cmath>
#include <memory>
#include <mutex>

namespace wheelchair_safety {

class SafetyNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle nh = getNodeHandle(), pnh = getPrivateNodeHandle();
    SafetyLimits limits;
    pnh.param("scan_timeout", limits.scan_timeout, limits.scan_timeout);
    pnh.param("pose_timeout", limits.pose_timeout, limits.pose_timeout);
    pnh.param("localization_timeout", limits.localization_timeout, limits.localization_timeout);
    pnh.param("max_position_std", limits.max_position_std, limits.max_position_std);
    pnh.param("max_heading_std", limits.max_heading_std, limits.max_heading_std);
    pnh.param("stop_distance", limits.stop_distance, limits.stop_distance);
    pnh.param("corridor_half_width", limits.corridor_half_width, limits.corridor_half_width);
    pnh.param("map_tolerance", limits.map_tolerance, limits.map_tolerance);
    pnh.param("min_obstacle_returns", limits.min_obstacle_returns, limits.min_obstacle_returns);
    pnh.param("driver_fault_grace", limits.driver_fault_grace, limits.driver_fault_grace);
    pnh.param<std::string>("map_frame", map_frame_, "map");
    pnh.param<std::string>("base_frame", base_frame_, "base_link");
    supervisor_ = std::make_unique<SafetySupervisor>(limits);
    tf_buffer_ = wheelchair_ros::sharedTfBuffer();  // one /tf listener per process

    stop_pub_ = nh.advertise<std_msgs::Bool>("safety/stop", 1, true);
    status_pub_ = nh.advertise<std_msgs::String>("safety/status", 1, true);
    subs_.push_back(nh.subscribe("map", 1, &SafetyNodelet::onMap, this));
    subs_.push_back(nh.subscribe("plan", 1, &SafetyNodelet::onPlan, this));
    subs_.push_back(nh.subscribe("scan", 5, &SafetyNodelet::onScan, this));
    subs_.push_back(nh.subscribe("kld_pose", 5, &SafetyNodelet::onEstimate, this));
    subs_.push_back(nh.subscribe("kld/localized", 5, &SafetyNodelet::onLocalized, this));
    subs_.push_back(nh.subscribe("base_driver/status", 5, &SafetyNodelet::onDriver, this));
    subs_.push_back(nh.subscribe("user_stop", 5, &SafetyNodelet::onUserStop, this));
    subs_.push_back(nh.subscribe("move_base_simple/goal", 5, &SafetyNodelet::onGoal, this));
    double rate = 20.0;
    pnh.param("rate", rate, rate);
    timer_ = nh.createTimer(ros::Duration(1.0 / rate), &SafetyNodelet::onTimer, this);
  }

  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onMap(wheelchair_ros::fromOccupancyGrid(*msg));
  }

  void onPlan(const nav_msgs::Path::ConstPtr& msg) {
    std::vector<Eigen::Vector2d> path;
    for (const auto& pose : msg->poses)
      path.emplace_back(pose.pose.position.x, pose.pose.position.y);
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onPath(std::move(path));
  }

  void onEstimate(const geometry_msgs::PoseWithCovarianceStamped::ConstPtr& msg) {
    const auto& c = msg->pose.covariance;  // row-major 6x6: x y z roll pitch yaw
    Eigen::Matrix3d cov;
    cov << c[0], c[1], c[5], c[6], c[7], c[11], c[30], c[31], c[35];
    std::lock_guard<std::mutex> lock(mutex_);
    covariance_ = cov;
    if (have_status_)  // until the localizer has said whether it is localized: no data yet
      supervisor_->onLocalization(msg->header.stamp.toSec(), localized_, cov, why_not_);
  }

  /// The localizer's verdict: data "localized" or the reason it is not.
  void onLocalized(const std_msgs::String::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    have_status_ = true;
    localized_ = msg->data == "localized";
    why_not_ = msg->data;
    supervisor_->onLocalization(ros::Time::now().toSec(), localized_, covariance_, why_not_);
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    geometry_msgs::TransformStamped laser_in_map;
    try {
      laser_in_map = tf_buffer_->lookupTransform(map_frame_, msg->header.frame_id,
                                                 msg->header.stamp, ros::Duration(0.05));
    } catch (const tf2::TransformException& e) {
      NODELET_WARN_THROTTLE(2.0, "scan skipped: no %s -> %s: %s", map_frame_.c_str(),
                            msg->header.frame_id.c_str(), e.what());
      return;  // the scan watchdog then runs out and stops the chair
    }
    const double yaw = tf2::getYaw(laser_in_map.transform.rotation);
    const Eigen::Vector2d origin(laser_in_map.transform.translation.x,
                                 laser_in_map.transform.translation.y);
    std::vector<Eigen::Vector2d> returns;
    for (size_t i = 0; i < msg->ranges.size(); ++i) {
      const double r = msg->ranges[i];
      if (!std::isfinite(r) || r < msg->range_min || r > msg->range_max) continue;
      const double a = yaw + msg->angle_min + i * msg->angle_increment;
      returns.push_back(origin + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onScan(msg->header.stamp.toSec(), returns);
  }

  void onDriver(const diagnostic_msgs::DiagnosticStatus::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onDriverStatus(ros::Time::now().toSec(),
                                msg->level >= diagnostic_msgs::DiagnosticStatus::ERROR,
                                msg->message);
  }

  void onUserStop(const std_msgs::Empty::ConstPtr&) {
    std::lock_guard<std::mutex> lock(mutex_);
    supervisor_->onUserStop(ros::Time::now().toSec());
  }

  /// A new goal is the rider's command to go on: the verdict goes out at once, before the
  /// planner's path reaches the controller (which ignores paths while stopped).
  void onGoal(const geometry_msgs::PoseStamped::ConstPtr&) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      supervisor_->onUserCommand(ros::Time::now().toSec());
    }
    update();
  }

  void onTimer(const ros::TimerEvent&) { update(); }

  void update() {
    geometry_msgs::TransformStamped base_in_map;
    bool have_pose = false;
    try {
      base_in_map = tf_buffer_->lookupTransform(map_frame_, base_frame_, ros::Time(0));
      have_pose = true;
    } catch (const tf2::TransformException&) {
    }
    std::lock_guard<std::mutex> lock(mutex_);
    if (have_pose)
      supervisor_->onPose(base_in_map.header.stamp.toSec(),
                          {base_in_map.transform.translation.x, base_in_map.transform.translation.y,
                           tf2::getYaw(base_in_map.transform.rotation)});
    const SafetyVerdict verdict = supervisor_->check(ros::Time::now().toSec());
    const std::string text =
        verdict.stop ? std::string(describe(verdict.reason)) + ": " + verdict.detail : "safe";
    if (first_ || verdict.stop != stopped_ || text != text_) {
      if (verdict.stop) NODELET_WARN("STOP: %s", text.c_str());
      std_msgs::Bool stop;
      stop.data = verdict.stop;
      stop_pub_.publish(stop);
      std_msgs::String status;
      status.data = text;
      status_pub_.publish(status);
      first_ = false;
      stopped_ = verdict.stop;
      text_ = text;
    }
  }

  std::mutex mutex_;
  std::unique_ptr<SafetySupervisor> supervisor_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  std::string map_frame_, base_frame_;
  bool have_status_ = false, localized_ = false;
  std::string why_not_ = "no localizer status yet";
  Eigen::Matrix3d covariance_ = Eigen::Matrix3d::Identity();
  ros::Publisher stop_pub_, status_pub_;
  std::vector<ros::Subscriber> subs_;
  ros::Timer timer_;
  bool first_ = true, stopped_ = false;
  std::string text_;
};

}  // namespace wheelchair_safety

PLUGINLIB_EXPORT_CLASS(wheelchair_safety::SafetyNodelet, nodelet::Nodelet)
