// Publishes a map file as a latched nav_msgs/OccupancyGrid on /map (+ /map_metadata, and the
// static_map service), like ROS map_server. Map file: first nodelet argument or ~map_file;
// frame: ~map_frame (map).
#include <nav_msgs/GetMap.h>
#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_ros/conversions.h>
#include <wheelchair_ros/parameters.h>
#include <pluginlib/class_list_macros.hpp>

#include "mapping_node_config.h"

namespace wheelchair_mapping {

class MapServerNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    ros::NodeHandle& nh = getNodeHandle();
    const auto config = wheelchair_ros::loadParameters<MapServerConfig>(getPrivateNodeHandle(),
                                                                        readMapServerConfig);
    const std::string path = getMyArgv().empty() ? config.map_file : getMyArgv().front();
    if (path.empty()) {
      NODELET_FATAL("no map file: give it as the first argument or as ~map_file");
      return;
    }
    try {
      map_ = wheelchair_ros::toOccupancyGrid(wheelchair_core::loadMap(path), config.map_frame,
                                             ros::Time::now());
    } catch (const wheelchair_core::MapFileError& e) {
      NODELET_FATAL("%s", e.what());  // publish nothing: a wrong map is worse than none
      return;
    }
    map_pub_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
    metadata_pub_ = nh.advertise<nav_msgs::MapMetaData>("map_metadata", 1, true);
    map_pub_.publish(map_);
    metadata_pub_.publish(map_.info);
    service_ = nh.advertiseService("static_map", &MapServerNodelet::onGetMap, this);
    NODELET_INFO("serving %s: %u x %u cells at %.3f m", path.c_str(), map_.info.width,
                 map_.info.height, map_.info.resolution);
  }

  bool onGetMap(nav_msgs::GetMap::Request&, nav_msgs::GetMap::Response& res) {
    res.map = map_;
    return true;
  }

  nav_msgs::OccupancyGrid map_;
  ros::Publisher map_pub_;
  ros::Publisher metadata_pub_;
  ros::ServiceServer service_;
};

}  // namespace wheelchair_mapping

PLUGINLIB_EXPORT_CLASS(wheelchair_mapping::MapServerNodelet, nodelet::Nodelet)
