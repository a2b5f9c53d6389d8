// ROS layer: files of installed packages, found at run time (the core stays ROS-free).
#pragma once

#include <ros/package.h>
#include <wheelchair_description/chair_params.h>

#include <string>

namespace wheelchair_description {

/// `relative` inside the share directory of ROS package `package`, found at run time through
/// ROS_PACKAGE_PATH (devel space, install space, an installed .deb wherever its prefix is);
/// `fallback` when the package is not on the path.
inline std::string packageFile(const std::string& package, const std::string& relative,
                               const std::string& fallback) {
  const std::string share = ros::package::getPath(package);
  return share.empty() ? fallback : share + "/" + relative;
}

/// The chair file of the wheelchair_description package found at run time: the default of
/// every nodelet's chair parameter file.
inline std::string chairParamsPathFromRos() {
  return packageFile("wheelchair_description", "config/chair.yaml", defaultChairParamsPath());
}

}  // namespace wheelchair_description
