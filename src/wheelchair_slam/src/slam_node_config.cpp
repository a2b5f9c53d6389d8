#include "slam_node_config.h"

#include <cmath>

namespace wheelchair_slam {

std::string SlamNodeConfig::validate() const {
  const std::string slam_problem = slam.validate();
  const std::string map_problem = map.validate();
  bool finite_start = true;
  for (double v : start_pose) finite_start = finite_start && std::isfinite(v);
  return wheelchair_core::ConfigChecks()
      .check(slam_problem.empty(), slam_problem)
      .check(map_problem.empty(), map_problem)
      .check(!map_frame.empty() && !odom_frame.empty() && !base_frame.empty(),
             "map_frame, odom_frame and base_frame must be named")
      .check(map_frame != odom_frame, "map_frame and odom_frame must differ")
      .nonNegative("tf_timeout", tf_timeout)
      .nonNegative("transform_tolerance", transform_tolerance)
      .positive("tf_rate", tf_rate)
      .positive("map_period", map_period)
      .check(!save_dir.empty(), "save_dir must be named")
      .check(start_pose.empty() || (start_pose.size() == 3 && finite_start),
             "start_pose must be [x, y, yaw] (finite) or empty")
      .check(start_pose.empty() || !continue_dir.empty(), "start_pose needs continue_dir")
      .result();
}

void readSlamNodeConfig(wheelchair_core::ConfigReader& r, SlamNodeConfig& c) {
  readSlamConfig(r, c.slam);
  wheelchair_mapping::readMapperConfig(r, c.map);
  r.renamed("global_frame", "map_frame");
  r.read("map_frame", c.map_frame);
  r.read("odom_frame", c.odom_frame);
  r.read("base_frame", c.base_frame);
  r.read("tf_timeout", c.tf_timeout);
  r.read("transform_tolerance", c.transform_tolerance);
  r.read("tf_rate", c.tf_rate);
  r.read("publish_tf", c.publish_tf);
  r.read("map_period", c.map_period);
  r.read("save_dir", c.save_dir);
  r.read("places_file", c.places_file);
  r.read("continue_dir", c.continue_dir);
  r.read("start_pose", c.start_pose);
}

}  // namespace wheelchair_slam
