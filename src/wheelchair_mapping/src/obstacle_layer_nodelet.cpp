// The live obstacle layer as a nodelet of the chair process: fuses /scan and /rear_scan (the
// rear laser behind the chair) at the localized laser pose (tf2 ~map_frame -> the scan's frame,
// while /localization/status says localized) into an
// ObstacleLayer on the grid of /map, and publishes it, latched, on /obstacles
// (nav_msgs/OccupancyGrid, same geometry as /map: 100 obstacle, 0 seen free, -1 no evidence)
// every ~publish_period s when it changed, decay included. A new /map starts a new layer; a map
// it refuses (any node can publish /map: too big for max_map_cells, broken) leaves the last good
// layer in place, so one bad message does not switch the live layer off while the chair drives.
// tf from the process's one buffer (wheelchair_ros::sharedTfBuffer): a listener of its own
// processed every /tf message a second time on a thread of its own.
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <wheelchair_core/callback_cpu.h>
#include <wheelchair_mapping/obstacle_layer.h>
#include <wheelchair_msgs/LocalizationStatus.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>
#include <wheelchair_ros/shared_tf.h>
#include <pluginlib/class_list_macros.hpp>

#include <memory>
#include <mutex>
#include <stdexcept>

#include "mapping_node_config.h"

namespace wheelchair_mapping {

class ObstacleLayerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    config_ = wheelchair_ros::loadParameters<ObstacleLayerNodeConfig>(getPrivateNodeHandle(),
                                                                      readObstacleLayerNodeConfig);
    tf_buffer_ = wheelchair_ros::sharedTfBuffer();
    pub_ = nh.advertise<nav_msgs::OccupancyGrid>("obstacles", 1, true);
    map_sub_ = nh.subscribe("map", 1, &ObstacleLayerNodelet::onMap, this);
    status_sub_ = nh.subscribe("localization/status", 1, &ObstacleLayerNodelet::onStatus, this);
    scan_sub_ = nh.subscribe("scan", 5, &ObstacleLayerNodelet::onScan, this);
    rear_scan_sub_ = nh.subscribe("rear_scan", 5, &ObstacleLayerNodelet::onScan, this);
    timer_ = nh.createWallTimer(ros::WallDuration(config_.publish_period),
                                [this](const ros::WallTimerEvent&) { publish(); });
  }

  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    std::unique_ptr<ObstacleLayer> layer;
    try {  // before the lock: a refused map changes nothing
      layer =
          std::make_unique<ObstacleLayer>(wheelchair_ros::fromOccupancyGrid(*msg), config_.layer);
    } catch (const std::invalid_argument& e) {
      NODELET_ERROR("obstacle layer: map refused, keeping the last good one: %s", e.what());
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    layer_ = std::move(layer);
    published_.clear();
  }

  void onStatus(const wheelchair_msgs::LocalizationStatus::ConstPtr& msg) {
    localized_ = msg->localized;
  }

  void onScan(const sensor_msgs::LaserScan::ConstPtr& msg) {
    const wheelchair_core::CallbackCpuScope cpu(getName());  // CPU per nodelet (callback_cpu.h)
    if (config_.require_localized && !localized_) {
      NODELET_INFO_THROTTLE(10.0, "scans not fused: not localized");
      return;
    }
    geometry_msgs::TransformStamped t;
    try {
      t = tf_buffer_->lookupTransform(config_.map_frame, msg->header.frame_id, msg->header.stamp,
                                      ros::Duration(config_.tf_timeout));
    } catch (const tf2::TransformException& e) {
      NODELET_WARN_THROTTLE(5.0, "scan skipped: no tf %s -> %s: %s", config_.map_frame.c_str(),
                            msg->header.frame_id.c_str(), e.what());
      return;
    }
    wheelchair_core::Pose2D pose;
    const bool upside_down = wheelchair_ros::laserPose2D(t.transform, pose);
    wheelchair_core::LaserScan2D scan = wheelchair_ros::fromLaserScanMsg(*msg);
    if (upside_down) wheelchair_core::mirrorScanAngles(scan);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!layer_) return;
    const InsertResult r = layer_->insert(scan, pose);
    if (!r.inserted) NODELET_WARN_THROTTLE(5.0, "scan skipped: %s", r.reason.c_str());
  }

  void publish() {
    wheelchair_core::OccupancyMap layer;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!layer_) return;
      layer_->decayTo(ros::Time::now().toSec());
      layer = layer_->layer();
      if (layer.data == published_) return;
      published_ = layer.data;
    }
    pub_.publish(wheelchair_ros::toOccupancyGrid(layer, config_.map_frame, ros::Time::now()));
  }

  ObstacleLayerNodeConfig config_;
  std::mutex mutex_;
  std::unique_ptr<ObstacleLayer> layer_;
  std::vector<int8_t> published_;
  bool localized_ = false;
  std::shared_ptr<tf2_ros::Buffer> tf_buffer_;
  ros::Publisher pub_;
  ros::Subscriber map_sub_, status_sub_, scan_sub_, rear_scan_sub_;
  ros::WallTimer timer_;
};

}  // namespace wheelchair_mapping

PLUGINLIB_EXPORT_CLASS(wheelchair_mapping::ObstacleLayerNodelet, nodelet::Nodelet)
