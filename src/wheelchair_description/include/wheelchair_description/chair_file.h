// ROS layer: where a nodelet finds the chair file, at run time. The core takes a path and
// knows nothing of where it was built or installed.
#pragma once

#include <ros/console.h>
#include <ros/node_handle.h>
#include <ros/package.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_ros/parameters.h>

#include <string>

namespace wheelchair_description {

/// wheelchair_description's config/chair.yaml, found through ROS_PACKAGE_PATH (devel space,
/// install space, an installed .deb wherever its prefix is). Throws wheelchair_core::ConfigError
/// when the package is not on the path.
inline std::string defaultChairFile() {
  const std::string share = ros::package::getPath("wheelchair_description");
  if (share.empty())
    throw wheelchair_core::ConfigError(
        "wheelchair_description is not on ROS_PACKAGE_PATH: no default chair file (set "
        "chair_file)");
  return share + "/config/chair.yaml";
}

/// `chair_file` as a nodelet's settings hold it: "" means defaultChairFile().
inline std::string resolveChairFile(const std::string& chair_file) {
  return chair_file.empty() ? defaultChairFile() : chair_file;
}

/// The chair of a nodelet: the file its private parameter `chair_file` names, else
/// defaultChairFile(). (The nodelet's loader reads `chair_file` too, so the key is known.)
/// Throws wheelchair_core::ConfigError, logged, naming the file and the problem.
inline ChairParams loadChairOf(const ros::NodeHandle& private_nh) {
  try {
    std::string path;
    wheelchair_ros::RosParameterSource(private_nh).get("chair_file", path);
    return loadChairParams(resolveChairFile(path));
  } catch (const wheelchair_core::ConfigError& e) {
    ROS_FATAL("%s: %s", private_nh.getNamespace().c_str(), e.what());
    throw;
  }
}

}  // namespace wheelchair_description
