// The tiny `main` shared by every node of the project: it loads one nodelet into its own
// process so that `rosrun <pkg> <node> _param:=value topic:=other` works without roslaunch.
#pragma once

#include <nodelet/loader.h>
#include <ros/ros.h>

#include <string>
#include <vector>

namespace wheelchair_ros {

/// Runs `nodelet_type` (e.g. "wheelchair_mapping/MapServerNodelet") as node `default_name`.
/// Command-line words that are not ROS remappings are passed to the nodelet as its argv.
inline int runNodeletMain(int argc, char** argv, const std::string& default_name,
                          const std::string& nodelet_type) {
  ros::init(argc, argv, default_name);
  nodelet::Loader loader(false);
  std::vector<std::string> args;
  ros::removeROSArgs(argc, argv, args);
  const nodelet::V_string nodelet_argv(args.size() > 1 ? args.begin() + 1 : args.end(), args.end());
  if (!loader.load(ros::this_node::getName(), nodelet_type, ros::names::getRemappings(),
                   nodelet_argv)) {
    ROS_FATAL("could not load nodelet %s", nodelet_type.c_str());
    return 1;
  }
  ros::spin();
  return 0;
}

}  // namespace wheelchair_ros
