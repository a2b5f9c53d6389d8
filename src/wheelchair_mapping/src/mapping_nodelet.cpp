// The paper's map making as a node: fuses /scan at the laser pose taken from tf2 (in the
// frame ~pose_frame: odom, the simulator's ground truth or the localizer's map) into the
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
#include <pluginlib/class_list_macros.hpp>

#include <memory>
#include <mutex>

namespace wheelchair_mapping {

class MappingNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    ros::NodeHandle& pnh = getPrivateNodeHandle();
    pose_frame_ = pnh.param<std::string>("pose_frame", "odom");
    tf_timeout_ = pnh.param("tf_timeout", 0.2);
    MapperConfig config;
    pnh.param("resolution", config.resolution, config.resolution);
    pnh.param("initial_size", config.initial_size, config.initial_size);
    int expected_beams = 0;
    pnh.param("expected_beams", expected_beams, 0);
    config.expected_beams = static_cast<size_t>(std::max(0, expected_beams));
    InverseSensorModel& m = config.model;
    pnh.param("p_occ_hit", m.p_occ_hit, m.p_occ_hit);
    pnh.param("p_occ_pass", m.p_occ_pass, m.p_occ_pass);
    pnh.param("max_insertion_range", m.max_insertion_range, m.max_insertion_range);
    pnh.param("no_return_is_free", m.no_return_is_free, m.no_return_is_free);
    pnh.param("no_return_range", m.no_return_range, m.no_return_range);
    pnh.param("beam_width", m.beam_width, m.beam_width);
    try {
      mapper_ = std::make_unique<BayesMapper>(config);
    } catch (const std::invalid_argument& e) {
      NODELET_FATAL("%s: not mapping", e.what());
      return;
    }
    tf_listener_ = std::make_unique<tf2_ros::TransformListener>(tf_buffer_, nh);
    map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    scan_sub_ = nh.subscribe("scan", 10, &MappingNodelet::onScan, this);
    save_srv_ = pnh.advertiseService("save_map", &MappingNodelet::onSave, this);
    get_srv_ = nh.advertiseService("dynamic_map", &MappingNodelet::onGetMap, this);
    timer_ = nh.createWallTimer(ros::WallDuration(pnh.param("publish_period", 2.0)),
                                [this](const ros::WallTimerEvent&) { publish(); });
  }

  /// Laser pose in pose_frame_ at the scan's time; false (with a reason) if unknown.
  bool laserPose(const sensor_msgs::LaserScan& msg, wheelchair_core::Pose2D& pose,
                 bool& upside_down, std::string& reason) {
    geometry_msgs::TransformStamped t;
    try {
      t = tf_buffer_.lookupTransform(pose_frame_, msg.header.frame_id, msg.header.stamp,
                                     ros::Duration(tf_timeout_));
    } catch (const tf2::TransformException& e) {
      reason = std::string("no tf ") + pose_frame_ + " -> " + msg.header.frame_id + ": " + e.what();
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
    return wheelchair_ros::toOccupancyGrid(mapper_->map(), pose_frame_, ros::Time::now());
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
    const std::string path = getPrivateNodeHandle().param<std::string>("save_path", "map.yaml");
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

  std::string pose_frame_;
  double tf_timeout_ = 0.2;
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
