// Everything the SLAM nodelet (the chair's mapping mode) reads from its private parameters: the
// SLAM core's SlamConfig (matcher/..., keyframes/..., odometry/..., loops/...), the published
// map's MapperConfig (resolution, p_occ_hit, ...) and the node's own frames, rates and files
// (one loader; unknown, renamed or invalid keys refuse the nodelet).
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_mapping/mapper_config.h>
#include <wheelchair_slam/slam_config.h>

#include <string>
#include <vector>

namespace wheelchair_slam {

struct SlamNodeConfig {
  SlamConfig slam;
  wheelchair_mapping::MapperConfig map;
  std::string map_frame = "map";
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  double tf_timeout = 0.2;           ///< [s] wait for the laser's odometry pose at a scan's stamp
  double transform_tolerance = 0.1;  ///< [s] map -> odom is stamped this far ahead
  double tf_rate = 20.0;             ///< [Hz] map -> odom repeated between scans
  /// false: no map -> odom (another localizer publishes it; bench/system's mapping case).
  bool publish_tf = true;
  double map_period = 2.0;  ///< [s] /map at most this often (grid rebuilt off the scans)
  /// Where ~save_map writes map.yaml/.pgm, trajectory.csv, graph.graph, graph.scans (read again
  /// at each call, so it can be set just before).
  std::string save_dir = "slam_map";
  /// Where ~save_place writes the named places (the HMI's places file; created if absent; read
  /// again at each call, so that a new home's file can be named just before).
  std::string places_file;
  /// A folder saved by ~save_map (or the slam tool) to continue; empty: a new map.
  std::string continue_dir;
  /// [x, y, yaw] of the laser in the continued map where this drive starts; empty: where the
  /// saved drive's map -> odom puts it (the same odometry frame goes on).
  std::vector<double> start_pose;

  std::string validate() const;
};

void readSlamNodeConfig(wheelchair_core::ConfigReader& reader, SlamNodeConfig& config);

}  // namespace wheelchair_slam
