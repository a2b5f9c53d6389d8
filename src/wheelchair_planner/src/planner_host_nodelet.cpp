// Planner host: loads a GlobalPlanner plugin by name, plans from tf map->base_link to goals from
// rviz (/move_base_simple/goal) and the ~make_plan service, publishes /plan and
// /plan_certificate, and replans when /map changes. It plans on /map plus the live obstacle
// layer /obstacles (its kOccupied cells; updateMap, the plugin's map-change path). Its one loader
// reads the host's keys, the shared settings (with the footprint of ~chair_file) and the plugin's
// own keys, and refuses anything else.
#include <wheelchair_core/callback_cpu.h>
#include <wheelchair_msgs/MakePlan.h>
#include <wheelchair_msgs/PlanCertificate.h>
#include <wheelchair_planner/global_planner.h>
#include <wheelchair_planner/planning_map.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>
#include <wheelchair_ros/shared_tf.h>

#include "certificate_message.h"
#include "host_parameters.h"

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <pluginlib/class_list_macros.hpp>
#include <pluginlib/class_loader.hpp>

#include <memory>
#include <mutex>
#include <optional>

namespace wheelchair_planner {

using wheelchair_core::ConfigError;
using wheelchair_msgs::MakePlan;

namespace {

/// The pose in the map frame, or nullopt with a reason if it is not finite / not in `map`.
std::optional<Pose2D> fromPoseStamped(const geometry_msgs::PoseStamped& ps,
                                      const std::string& map_frame, std::string& reason) {
  const Pose2D p = wheelchair_ros::toPose2D(ps.pose);
  if (!p.isFinite() || !wheelchair_ros::isNormalized(ps.pose.orientation)) {
    reason = "pose is not finite or its quaternion is not normalized";
    return std::nullopt;
  }
  if (!ps.header.frame_id.empty() && ps.header.frame_id != map_frame) {
    reason = "pose is in frame '" + ps.header.frame_id + "', expected '" + map_frame + "'";
    return std::nullopt;
  }
  return p;
}

}  // namespace

class PlannerHostNodelet : public nodelet::Nodelet {
 public:
  PlannerHostNodelet() : loader_("wheelchair_planner", "wheelchair_planner::GlobalPlanner") {}

 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    const HostSetup setup = wheelchair_ros::loadParameters<HostSetup>(
        pnh, [this](wheelchair_core::ConfigReader& reader, HostSetup& s) { configure(reader, s); });
    planner_name_ = setup.host.planner;
    map_frame_ = setup.host.map_frame;
    base_frame_ = setup.host.base_frame;
    max_pose_age_ = setup.host.max_pose_age;
    map_limits_ = setup.host.map_limits;
    tf_buffer_ = wheelchair_ros::sharedTfBuffer();  // one /tf listener per process
    plan_pub_ = nh.advertise<nav_msgs::Path>("plan", 1, true);
    cert_pub_ = nh.advertise<wheelchair_msgs::PlanCertificate>("plan_certificate", 1, true);
    potential_pub_ = pnh.advertise<nav_msgs::OccupancyGrid>("potential", 1, true);
    map_sub_ = nh.subscribe("map", 1, &PlannerHostNodelet::onMap, this);
    obstacles_sub_ = nh.subscribe("obstacles", 1, &PlannerHostNodelet::onObstacles, this);
    goal_sub_ = nh.subscribe("move_base_simple/goal", 1, &PlannerHostNodelet::onGoal, this);
    service_ = pnh.advertiseService("make_plan", &PlannerHostNodelet::onMakePlan, this);
    NODELET_INFO("planner host: %s, waiting for /map", planner_name_.c_str());
  }

  /// The loader's reading (readHostSetup), the plugin created by pluginlib.
  void configure(wheelchair_core::ConfigReader& reader, HostSetup& s) {
    planner_ = readHostSetup(reader, s, [&](const std::string& name) {
      try {
        return loader_.createInstance(name);
      } catch (const pluginlib::PluginlibException& e) {
        std::string known;
        for (const std::string& declared : loader_.getDeclaredClasses())
          known += (known.empty() ? "" : ", ") + declared;
        throw ConfigError(reader.source().where() + ": planner '" + name +
                          "' cannot be loaded (known: " + known + "): " + e.what());
      }
    });
  }

  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    // Any node can publish /map: a broken or oversized map is refused before anything is
    // prepared, and the planner keeps the last good one (it went without any before).
    const std::string problem = wheelchair_ros::occupancyGridProblem(*msg, map_limits_);
    if (!problem.empty()) {
      NODELET_ERROR("planner host: map refused, keeping the last good one: %s", problem.c_str());
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::WallTime started = ros::WallTime::now();
    try {
      static_map_ = wheelchair_ros::fromOccupancyGrid(*msg, map_limits_);
      planner_->setMap(static_map_);
      planned_on_ = static_map_.data;
      have_map_ = true;
    } catch (const std::exception& e) {
      have_map_ = false;
      NODELET_ERROR("planner host: map rejected: %s", e.what());
      return;
    }
    NODELET_INFO("planner host: map %ux%u at %.3f m, prepared in %.3f s", msg->info.width,
                 msg->info.height, msg->info.resolution, (ros::WallTime::now() - started).toSec());
    applyObstacles();
    if (active_goal_) planAndPublish(std::nullopt, *active_goal_);  // replan on the new map
  }

  /// The live obstacle layer: the next plan is made on /map plus its obstacles. No replan here:
  /// who drives (the navigator) decides when the change matters.
  void onObstacles(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    // Any node can publish it too: a broken layer is refused (a throw here aborted the process).
    const std::string problem = wheelchair_ros::occupancyGridProblem(*msg, map_limits_);
    if (!problem.empty()) {
      NODELET_ERROR("planner host: obstacle layer refused, keeping the last good one: %s",
                    problem.c_str());
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    obstacles_ = wheelchair_ros::fromOccupancyGrid(*msg, map_limits_);
    if (have_map_) applyObstacles();
  }

  /// static_map_ + obstacles_ to the plugin (its map-change path); a layer on another grid than
  /// the map's is ignored with a warning (the plan is then made on the map alone).
  void applyObstacles() {
    if (!obstacles_) return;
    wheelchair_core::OccupancyMap merged;
    try {
      merged = withObstacles(static_map_, *obstacles_);
    } catch (const std::invalid_argument& e) {
      NODELET_WARN_THROTTLE(10.0, "planner host: /obstacles ignored: %s", e.what());
      merged = static_map_;
    }
    if (merged.data == planned_on_) return;
    const ros::WallTime started = ros::WallTime::now();
    try {
      planner_->updateMap(merged);
      planned_on_ = std::move(merged.data);
    } catch (const std::exception& e) {
      NODELET_ERROR("planner host: map with obstacles rejected: %s", e.what());
      planner_->setMap(static_map_);
      planned_on_ = static_map_.data;
      return;
    }
    NODELET_DEBUG("planner host: obstacle layer applied in %.4f s",
                  (ros::WallTime::now() - started).toSec());
  }

  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    std::lock_guard<std::mutex> lock(mutex_);
    std::string reason;
    const auto goal = fromPoseStamped(*msg, map_frame_, reason);
    if (!goal) {
      NODELET_WARN_THROTTLE(1.0, "planner host: goal rejected: %s", reason.c_str());
      active_goal_.reset();  // the rider asked for something else than the old goal: stop
      publishFailure("goal rejected: " + reason);
      return;
    }
    active_goal_ = goal;
    planAndPublish(std::nullopt, *goal);
  }

  bool onMakePlan(MakePlan::Request& req, MakePlan::Response& res) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    std::lock_guard<std::mutex> lock(mutex_);
    std::string reason;
    const auto goal = fromPoseStamped(req.goal, map_frame_, reason);
    std::optional<Pose2D> start;
    if (goal && req.use_start) {
      start = fromPoseStamped(req.start, map_frame_, reason);
      if (!start) reason = "start " + reason;
    } else if (!goal) {
      reason = "goal " + reason;
    }
    if (!goal || (req.use_start && !start)) {
      res.success = false;
      res.reason = reason;
      res.certificate.failure_reason = reason;
      return true;
    }
    const auto result = planAndPublish(start, *goal);
    res.success = result.first.success;
    res.reason = result.first.failure_reason;
    res.certificate = toPlanCertificateMsg(result.first, result.second.header);
    res.plan = result.second;
    return true;
  }

  /// Plans from `start` (or the current tf pose) and publishes path + certificate.
  std::pair<Certificate, nav_msgs::Path> planAndPublish(std::optional<Pose2D> start,
                                                        const Pose2D& goal) {
    Certificate cert;
    nav_msgs::Path path;
    path.header.frame_id = map_frame_;
    path.header.stamp = ros::Time::now();
    if (!have_map_) {
      cert.failure_reason = "no map received on /map yet";
    } else if (!start && !(start = currentPose(cert.failure_reason))) {
      // reason filled by currentPose
    } else {
      std::vector<Pose2D> plan;
      try {
        planner_->makePlan(*start, goal, plan, cert);
      } catch (const std::exception& e) {
        cert.success = false;
        cert.failure_reason = std::string("planner threw: ") + e.what();
        plan.clear();
      }
      path = wheelchair_ros::toPathMsg(plan, map_frame_, path.header.stamp);
    }
    if (!cert.success) {
      NODELET_WARN_THROTTLE(1.0, "planner host: no plan: %s", cert.failure_reason.c_str());
    }
    plan_pub_.publish(path);  // an empty path on failure: the controller stops
    cert_pub_.publish(toPlanCertificateMsg(cert, path.header));
    wheelchair_core::OccupancyMap potential;
    if (have_map_ && planner_->potentialGrid(potential)) {
      potential_pub_.publish(
          wheelchair_ros::toOccupancyGrid(potential, map_frame_, path.header.stamp));
    }
    return {cert, path};
  }

  std::optional<Pose2D> currentPose(std::string& reason) {
    try {
      const auto t = tf_buffer_->lookupTransform(map_frame_, base_frame_, ros::Time(0));
      const double age = (ros::Time::now() - t.header.stamp).toSec();
      if (!t.header.stamp.isZero() && age > max_pose_age_) {
        reason = "tf " + map_frame_ + "->" + base_frame_ + " is " + std::to_string(age) +
                 " s old (max " + std::to_string(max_pose_age_) + ")";
        return std::nullopt;
      }
      return wheelchair_ros::toPose2D(t.transform);
    } catch (const tf2::TransformException& e) {
      reason = std::string("no tf ") + map_frame_ + "->" + base_frame_ + ": " + e.what();
      return std::nullopt;
    }
  }

  /// An empty /plan (the controller stops the chair) and a failed certificate with the reason.
  void publishFailure(const std::string& reason) {
    Certificate cert;
    cert.failure_reason = reason;
    nav_msgs::Path path;
    path.header.frame_id = map_frame_;
    path.header.stamp = ros::Time::now();
    plan_pub_.publish(path);
    cert_pub_.publish(toPlanCertificateMsg(cert, path.header));
  }

  pluginlib::ClassLoader<GlobalPlanner> loader_;
  boost::shared_ptr<GlobalPlanner> planner_;
  std::string planner_name_, map_frame_, base_frame_;
  double max_pose_age_ = 0.0;
  wheelchair_core::MapLimits map_limits_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  ros::Publisher plan_pub_, cert_pub_, potential_pub_;
  ros::Subscriber map_sub_, obstacles_sub_, goal_sub_;
  wheelchair_core::OccupancyMap static_map_;                ///< the last /map
  std::optional<wheelchair_core::OccupancyMap> obstacles_;  ///< the last /obstacles
  std::vector<int8_t> planned_on_;                          ///< cells of the map the plugin has now
  ros::ServiceServer service_;
  std::mutex mutex_;
  bool have_map_ = false;
  std::optional<Pose2D> active_goal_;
};

}  // namespace wheelchair_planner

PLUGINLIB_EXPORT_CLASS(wheelchair_planner::PlannerHostNodelet, nodelet::Nodelet)
