// The paper's map making as a node: fuses /scan at the laser pose taken from tf2 (in the
// frame ~map_frame: odom, the simulator's ground truth or the localizer's map) into the
// Bayesian grid, publishes it on /map every ~publish_period s and on request (dynamic_map),
// and saves it as YAML + PGM with ~save_map (to ~save_path).
#include <nav_msgs/GetMap.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>
#include <mutex>

#include "mapping_node_config.h"

namespace wheelchair_mapping {

class MappingNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    config_ = wheelchair_ros::loadParameters<MappingNodeConfig>(pnh, readMappingNodeConfig);
    mapper_ = std::make_unique<BayesMapper>(config_.mapper);  // a valid config: no throw
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_, nh);
    map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    scan_sub_ = nh.subscribe("scan", 10, &MappingNodelet::onScan, this);
    save_srv_ = pnh.advertiseService("save_map", &MappingNodelet::onSave, this);
    get_srv_ = nh.advertiseService("dynamic_map", &MappingNodelet::onGetMap, this);
    timer_ = nh.createWallTimer(ros::WallDuration(config_.publish_period),
                                [this](const ros::WallTimerEvent&) { publish(); });
  }

  /// Laser pose in the map frame at the scan's time; false (with a reason) if unknown.
  bool laserPose(const sensor_msgs::LaserScan& msg, wheelchair_core::Pose2D& pose,
                 bool& upside_down, std::string& reason) {
    geometry_msgs::TransformStamped t;
    try {
      t = tf_buffer_.lookupTransform(config_.map_frame, msg.header.frame_id, msg.header.stamp,
                                     ros::Duration(config_.tf_timeout));
    } catch (const tf2::TransformException& e) {
      reason = "no tf " + config_.map_frame + " -> " + msg.header.frame_id + ": " + e.what();
      return false;
    }
    upside_down = wheelchair_ros::laserPose2D(t.transform, pose);
    return true;
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    wheelchair_core::Pose2D pose;
    bool upside_down = false;
    std::string reason;
    if (!laserPose(*msg, pose, upside_down, reason)) {
      NODELET_WARN_THROTTLE(5.0, "scan skipped: %s", reason.c_str());
      return;
    }
    wheelchair_core::LaserScan2D scan = wheelchair_ros::fromLaserScanMsg(*msg);
    if (upside_down) wheelchair_core::mirrorScanAngles(scan);
    std::lock_guard<std::mutex> lock(mutex_);
    const InsertResult r = mapper_->insert(scan, pose);
    if (!r.inserted) {
      NODELET_WARN_THROTTLE(5.0, "scan skipped: %s", r.reason.c_str());
      return;
    }
    changed_ = true;
  }

  nav_msgs::OccupancyGrid currentMap() {
    std::lock_guard<std::mutex> lock(mutex_);
    changed_ = false;
    return wheelchair_ros::toOccupancyGrid(mapper_->map(), config_.map_frame, ros::Time::now());
  }

  void publish() {
    if (changed_) map_pub_.publish(currentMap());
  }

  bool onGetMap(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& res) {
    res.map = currentMap();
    map_pub_.publish(res.map);
    return true;
  }

  bool onSave(std_srvs::Trigger::Request&, std_srvs::Trigger::Response& res) {
    const std::string path =
        getPrivateNodeHandle().param<std::string>("save_path", config_.save_path);
    try {
      wheelchair_core::OccupancyMap map;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        map = mapper_->map();
      }
      wheelchair_core::saveMap(map, path);
      res.success = true;
      res.message = "saved " + path;
    } catch (const wheelchair_core::MapFileError& e) {
      res.success = false;
      res.message = e.what();
      NODELET_ERROR("%s", e.what());
    }
    return true;
  }

  MappingNodeConfig config_;
  std::unique_ptr<BayesMapper> mapper_;
  std::mutex mutex_;
  bool changed_ = false;
  tf2_ros::Buffer tf_buffer_;
  std::unique_ptr<tf2_ros::TransformListener> tf_listener_;
  ros::Publisher map_pub_;
  ros::Subscriber scan_sub_;
  ros::ServiceServer save_srv_;
  ros::ServiceServer get_srv_;
  ros::WallTimer timer_;
};

}  // namespace wheelchair_mapping

PLUGINLIB_EXPORT_CLASS(wheelchair_mapping::MappingNodelet, nodelet::Nodelet)
