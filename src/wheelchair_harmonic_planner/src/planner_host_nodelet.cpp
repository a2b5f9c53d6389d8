// Planner host: loads a GlobalPlanner plugin by name, plans from tf map->base_link to goals from
// rviz (/move_base_simple/goal) and the ~make_plan service, publishes /plan and
// /plan_certificate, and replans when /map changes.
#include <wheelchair_description/chair_file.h>
#include <wheelchair_harmonic_planner/footprint.h>
#include <wheelchair_harmonic_planner/global_planner.h>
#include <wheelchair_msgs/MakePlan.h>
#include <wheelchair_msgs/PlanCertificate.h>
#include <wheelchair_ros/conversions.h>

#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <tf2/utils.h>
#include <wheelchair_ros/shared_tf.h>
#include <pluginlib/class_list_macros.hpp>
#include <pluginlib/class_loader.hpp>

#include <cmath>
#include <memory>
#include <mutex>
#include <optional>

namespace wheelchair_harmonic_planner {

using wheelchair_msgs::MakePlan;
using wheelchair_msgs::PlanCertificate;

namespace {

geometry_msgs::PoseStamped toPoseStamped(const Pose2D& p, const std_msgs::Header& header) {
  geometry_msgs::PoseStamped ps;
  ps.header = header;
  ps.pose.position.x = p.x;
  ps.pose.position.y = p.y;
  ps.pose.orientation.z = std::sin(0.5 * p.yaw);
  ps.pose.orientation.w = std::cos(0.5 * p.yaw);
  return ps;
}

/// The pose in the map frame, or nullopt with a reason if it is not finite / not in `map`.
std::optional<Pose2D> fromPoseStamped(const geometry_msgs::PoseStamped& ps,
                                      const std::string& map_frame, std::string& reason) {
  const auto& q = ps.pose.orientation;
  const Pose2D p{ps.pose.position.x, ps.pose.position.y, tf2::getYaw(ps.pose.orientation)};
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.yaw) ||
      std::abs(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w - 1.0) > 1e-3) {
    reason = "pose is not finite or its quaternion is not normalized";
    return std::nullopt;
  }
  if (!ps.header.frame_id.empty() && ps.header.frame_id != map_frame) {
    reason = "pose is in frame '" + ps.header.frame_id + "', expected '" + map_frame + "'";
    return std::nullopt;
  }
  return p;
}

PlanCertificate toMsg(const Certificate& c, const std_msgs::Header& header);

}  // namespace

class PlannerHostNodelet : public nodelet::Nodelet {
 public:
  PlannerHostNodelet()
      : loader_("wheelchair_harmonic_planner", "wheelchair_harmonic_planner::GlobalPlanner") {}

 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    pnh.param<std::string>("planner", planner_name_, "wheelchair_harmonic_planner/HarmonicPlanner");
    pnh.param<std::string>("map_frame", map_frame_, "map");
    pnh.param<std::string>("base_frame", base_frame_, "base_link");
    pnh.param("max_pose_age", max_pose_age_, 0.5);
    readPlannerParams(pnh);
    planner_ = loader_.createInstance(planner_name_);  // throws (nodelet fails) on a bad name
    tf_buffer_ = wheelchair_ros::sharedTfBuffer();     // one /tf listener per process
    plan_pub_ = nh.advertise<nav_msgs::Path>("plan", 1, true);
    cert_pub_ = nh.advertise<PlanCertificate>("plan_certificate", 1, true);
    potential_pub_ = pnh.advertise<nav_msgs::OccupancyGrid>("potential", 1, true);
    map_sub_ = nh.subscribe("map", 1, &PlannerHostNodelet::onMap, this);
    goal_sub_ = nh.subscribe("move_base_simple/goal", 1, &PlannerHostNodelet::onGoal, this);
    service_ = pnh.advertiseService("make_plan", &PlannerHostNodelet::onMakePlan, this);
    NODELET_INFO("planner host: %s, waiting for /map", planner_name_.c_str());
  }

  /// Every private parameter except the host's own goes to the plugin as a string. The chair's
  /// inscribed radius comes from wheelchair_description's chair.yaml unless set here.
  void readPlannerParams(ros::NodeHandle& pnh) {
    std::vector<std::string> names;
    pnh.getParamNames(names);
    const std::string prefix = pnh.getNamespace() + "/";
    for (const std::string& full : names) {
      if (full.compare(0, prefix.size(), prefix) != 0) continue;
      const std::string key = full.substr(prefix.size());
      XmlRpc::XmlRpcValue v;
      if (key.find('/') != std::string::npos || !pnh.getParam(key, v)) continue;
      if (key == "planner" || key == "map_frame" || key == "base_frame" || key == "max_pose_age" ||
          key == "chair_params")
        continue;  // the host's own
      switch (v.getType()) {
        case XmlRpc::XmlRpcValue::TypeDouble:
          params_[key] = std::to_string(double(v));
          break;
        case XmlRpc::XmlRpcValue::TypeInt:
          params_[key] = std::to_string(int(v));
          break;
        case XmlRpc::XmlRpcValue::TypeBoolean:
          params_[key] = bool(v) ? "true" : "false";
          break;
        case XmlRpc::XmlRpcValue::TypeString:
          params_[key] = std::string(v);
          break;
        default:
          break;
      }
    }
    if (params_.count("inscribed_radius") == 0 || params_.count("footprint") == 0) {
      std::string chair_file;
      pnh.param<std::string>("chair_params", chair_file,
                             wheelchair_description::defaultChairFile());
      const auto chair = wheelchair_description::loadChairParams(chair_file);
      if (params_.count("inscribed_radius") == 0)
        params_["inscribed_radius"] = std::to_string(chair.inscribedRadius());
      if (params_.count("footprint") == 0) {  // the polygon whose sweep every plan must clear
        std::vector<Vertex> polygon;
        for (const auto& v : chair.footprint) polygon.push_back({v.x(), v.y()});
        params_["footprint"] = formatFootprint(polygon);
      }
    }
  }

  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    const ros::WallTime started = ros::WallTime::now();
    try {
      planner_->initialize(planner_name_, wheelchair_ros::fromOccupancyGrid(*msg), params_);
      have_map_ = true;
    } catch (const std::exception& e) {
      have_map_ = false;
      NODELET_ERROR("planner host: map rejected: %s", e.what());
      return;
    }
    NODELET_INFO("planner host: map %ux%u at %.3f m, prepared in %.3f s", msg->info.width,
                 msg->info.height, msg->info.resolution, (ros::WallTime::now() - started).toSec());
    if (active_goal_) planAndPublish(std::nullopt, *active_goal_);  // replan on the new map
  }

  void onGoal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
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
    res.certificate = toMsg(result.first, result.second.header);
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
      for (const Pose2D& p : plan) path.poses.push_back(toPoseStamped(p, path.header));
    }
    if (!cert.success) {
      NODELET_WARN_THROTTLE(1.0, "planner host: no plan: %s", cert.failure_reason.c_str());
    }
    plan_pub_.publish(path);  // an empty path on failure: the controller stops
    cert_pub_.publish(toMsg(cert, path.header));
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
      return Pose2D{t.transform.translation.x, t.transform.translation.y,
                    tf2::getYaw(t.transform.rotation)};
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
    cert_pub_.publish(toMsg(cert, path.header));
  }

  pluginlib::ClassLoader<GlobalPlanner> loader_;
  boost::shared_ptr<GlobalPlanner> planner_;
  std::string planner_name_, map_frame_, base_frame_;
  double max_pose_age_ = 0.5;
  ParameterMap params_;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  ros::Publisher plan_pub_, cert_pub_, potential_pub_;
  ros::Subscriber map_sub_, goal_sub_;
  ros::ServiceServer service_;
  std::mutex mutex_;
  bool have_map_ = false;
  std::optional<Pose2D> active_goal_;
};

namespace {

PlanCertificate toMsg(const Certificate& c, const std_msgs::Header& header) {
  PlanCertificate m;
  m.header = header;
  m.success = c.success;
  m.planner = c.planner;
  m.failure_reason = c.failure_reason;
  m.solver_iterations = c.solver_iterations;
  m.solver_residual = c.solver_residual;
  m.solver_converged = c.solver_converged;
  m.warm_started = c.warm_started;
  m.descent_reached_goal = c.descent_reached_goal;
  m.plateau_steps = c.plateau_steps;
  m.min_gradient = c.min_gradient;
  m.length = c.length;
  m.max_curvature = c.max_curvature;
  m.min_clearance = c.min_clearance;
  m.min_clearance_point.x = c.min_clearance_x;
  m.min_clearance_point.y = c.min_clearance_y;
  m.clearance.assign(c.clearance.begin(), c.clearance.end());
  m.planning_time = c.planning_time;
  m.path_stage = c.path_stage;
  m.footprint_checked = c.footprint_checked;
  m.footprint_clearance = c.footprint_clearance;
  m.footprint_clearance_point.x = c.footprint_clearance_x;
  m.footprint_clearance_point.y = c.footprint_clearance_y;
  m.sweep_poses = c.sweep_poses;
  m.first_stage_sweep = c.first_stage_sweep;
  m.search_expansions = c.search_expansions;
  m.search_time = c.search_time;
  return m;
}

}  // namespace

}  // namespace wheelchair_harmonic_planner

PLUGINLIB_EXPORT_CLASS(wheelchair_harmonic_planner::PlannerHostNodelet, nodelet::Nodelet)
