// The chair's mapping mode (issue 23): graph SLAM live on /scan and the laser's odometry pose
// from tf (odom_frame -> the scan's frame), publishing tf map_frame -> odom_frame and a latched
// /map at most every ~map_period s. The loop closing, optimization and the grid run on
// LiveSlam's worker thread, never in the scan callback. Services: ~save_map (std_srvs/Trigger:
// map.yaml/.pgm, trajectory.csv, graph.graph + graph.scans into ~save_dir) and ~save_place
// (wheelchair_msgs/SavePlace: the base's current pose as a named place in ~places_file, the
// HMI's file, written with wheelchair_hmi's savePlaces).
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <wheelchair_hmi/places.h>
#include <wheelchair_hmi/places_file.h>
#include <wheelchair_msgs/SavePlace.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>
#include <wheelchair_slam/live_slam.h>
#include <pluginlib/class_list_macros.hpp>

#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <optional>

#include "slam_node_config.h"

namespace wheelchair_slam {

class SlamNodelet : public nodelet::Nodelet {
 public:
  // The worker publishes /map: stop it before the publisher goes (members die in reverse).
  ~SlamNodelet() override { slam_.reset(); }

 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    config_ = wheelchair_ros::loadParameters<SlamNodeConfig>(pnh, readSlamNodeConfig);
    // Everything that can refuse the nodelet comes before the first ROS object (a publisher
    // destroyed after a refusal outlives the node handles it was made with).
    std::optional<SavedSlam> saved;
    if (!config_.continue_dir.empty()) {
      try {
        saved = loadSlam(config_.continue_dir, config_.slam);
      } catch (const std::exception& e) {
        const std::string problem = pnh.getNamespace() + ": continue_dir: " + e.what();
        ROS_FATAL("%s", problem.c_str());  // as loadParameters reports a refusal
        throw wheelchair_core::ConfigError(problem);
      }
    }
    map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    auto on_map = [this](const wheelchair_core::OccupancyMap& map) {
      map_pub_.publish(wheelchair_ros::toOccupancyGrid(map, config_.map_frame, ros::Time::now()));
    };
    if (!saved) {
      slam_ = std::make_unique<LiveSlam>(config_.slam, config_.map, config_.map_period, on_map);
    } else {
      std::optional<wheelchair_core::Pose2D> start;
      if (config_.start_pose.size() == 3)
        start = wheelchair_core::Pose2D{config_.start_pose[0], config_.start_pose[1],
                                        config_.start_pose[2]};
      NODELET_INFO("continuing the map in %s (%zu scans)", config_.continue_dir.c_str(),
                   saved->scans.size());
      slam_ = std::make_unique<LiveSlam>(config_.slam, config_.map, config_.map_period, on_map,
                                         std::move(*saved), start);
    }
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_, nh);
    scan_sub_ = nh.subscribe("scan", 5, &SlamNodelet::onScan, this);
    save_srv_ = pnh.advertiseService("save_map", &SlamNodelet::onSaveMap, this);
    place_srv_ = pnh.advertiseService("save_place", &SlamNodelet::onSavePlace, this);
    tf_timer_ = nh.createTimer(ros::Duration(1.0 / config_.tf_rate),
                               [this](const ros::TimerEvent&) { publishMapToOdom(); });
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    geometry_msgs::TransformStamped t;
    try {
      t = tf_buffer_.lookupTransform(config_.odom_frame, msg->header.frame_id, msg->header.stamp,
                                     ros::Duration(config_.tf_timeout));
    } catch (const tf2::TransformException& e) {
      NODELET_WARN_THROTTLE(5.0, "scan skipped: no odometry pose of %s in %s: %s",
                            msg->header.frame_id.c_str(), config_.odom_frame.c_str(), e.what());
      return;
    }
    wheelchair_core::Pose2D odometry;
    const bool upside_down = wheelchair_ros::laserPose2D(t.transform, odometry);
    wheelchair_core::LaserScan2D scan = wheelchair_ros::fromLaserScanMsg(*msg);
    if (upside_down) wheelchair_core::mirrorScanAngles(scan);
    if (const std::string problem = wheelchair_core::scanGeometryProblem(scan); !problem.empty()) {
      NODELET_WARN_THROTTLE(5.0, "scan skipped: %s", problem.c_str());
      return;
    }
    if (!slam_->addScan(scan, odometry)) {
      NODELET_WARN_THROTTLE(5.0,
                            "scan at %.3f not used (older than the last, or not yet located "
                            "in the continued map)",
                            msg->header.stamp.toSec());
      return;
    }
    publishMapToOdom();
  }

  void publishMapToOdom() {
    if (!config_.publish_tf || slam_->scans() == 0) return;
    geometry_msgs::TransformStamped t;
    t.header.frame_id = config_.map_frame;
    t.header.stamp = ros::Time::now() + ros::Duration(config_.transform_tolerance);
    t.child_frame_id = config_.odom_frame;
    t.transform = wheelchair_ros::toTransformMsg(slam_->mapToOdom());
    std::lock_guard<std::mutex> lock(tf_mutex_);
    if (t.header.stamp <= last_tf_stamp_) return;  // tf2 ignores (and warns about) a repeat
    last_tf_stamp_ = t.header.stamp;
    tf_broadcaster_.sendTransform(t);
  }

  bool onSaveMap(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    const std::string dir = getPrivateNodeHandle().param<std::string>("save_dir", config_.save_dir);
    try {
      std::filesystem::create_directories(dir);
      slam_->save(dir);
      res.success = true;
      res.message = "saved the map of " + std::to_string(slam_->scans()) + " scans in " + dir;
      NODELET_INFO("%s", res.message.c_str());
    } catch (const std::exception& e) {
      res.success = false;
      res.message = e.what();
      NODELET_ERROR("save_map: %s", e.what());
    }
    return true;
  }

  bool onSavePlace(wheelchair_msgs::SavePlace::Request& req,
                   wheelchair_msgs::SavePlace::Response& res) {
    res.success = false;
    const std::string places_file =
        getPrivateNodeHandle().param<std::string>("places_file", config_.places_file);
    if (places_file.empty()) {
      res.message = "no places_file is set: places cannot be saved";
      return true;
    }
    geometry_msgs::TransformStamped t;
    try {
      t = tf_buffer_.lookupTransform(config_.map_frame, config_.base_frame, ros::Time(0),
                                     ros::Duration(config_.tf_timeout));
    } catch (const tf2::TransformException& e) {
      res.message = "the chair's pose in the map is not known yet";
      NODELET_WARN("save_place: %s", e.what());
      return true;
    }
    try {
      std::vector<wheelchair_hmi::Place> places;
      // A new home's first place starts the file; an existing file keeps its places and keys.
      if (std::ifstream(places_file)) places = wheelchair_hmi::loadPlaces(places_file);
      wheelchair_hmi::Place place;
      place.name = wheelchair_hmi::placeId(req.name);
      place.room =
          wheelchair_hmi::placeId(req.room).empty() ? "places" : wheelchair_hmi::placeId(req.room);
      place.pose = wheelchair_ros::toPose2D(t.transform);
      if (const std::string p = wheelchair_hmi::placeNameProblem(place.name, places); !p.empty()) {
        res.message = p;
        return true;
      }
      places.push_back(place);
      wheelchair_hmi::savePlaces(places_file, places);
      res.success = true;
      res.message = "saved " + place.name + " in " + place.room;
      NODELET_INFO("save_place: %s at (%.2f, %.2f, %.2f) in %s", place.name.c_str(), place.pose.x,
                   place.pose.y, place.pose.yaw, places_file.c_str());
    } catch (const std::exception& e) {
      res.message = e.what();
      NODELET_ERROR("save_place: %s", e.what());
    }
    return true;
  }

  SlamNodeConfig config_;
  std::unique_ptr<LiveSlam> slam_;
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  std::mutex tf_mutex_;
  ros::Time last_tf_stamp_;
  ros::Publisher map_pub_;
  ros::Subscriber scan_sub_;
  ros::ServiceServer save_srv_, place_srv_;
  ros::Timer tf_timer_;
};

}  // namespace wheelchair_slam

PLUGINLIB_EXPORT_CLASS(wheelchair_slam::SlamNodelet, nodelet::Nodelet)
