// Everything the mapping nodelet reads from its private parameters: the mapper's MapperConfig
// and the node's own frame and timings (one loader; unknown, renamed or invalid keys refuse the
// nodelet).
#pragma once

#include <wheelchair_core/config.h>
#include <wheelchair_mapping/mapper_config.h>
#include <wheelchair_mapping/obstacle_layer.h>

#include <string>

namespace wheelchair_mapping {

struct MappingNodeConfig {
  MapperConfig mapper;
  /// The frame the map is built and published in, where the laser pose is looked up: odom,
  /// the simulator's ground truth or the localizer's map (was pose_frame).
  std::string map_frame = "odom";
  double tf_timeout = 0.2;      ///< [s] wait for the laser pose at a scan's stamp
  double publish_period = 2.0;  ///< [s] /map when it changed
  /// Where ~save_map writes (re-read when the service is called, so it can be set just before).
  std::string save_path = "map.yaml";

  std::string validate() const;
};

void readMappingNodeConfig(wheelchair_core::ConfigReader& reader, MappingNodeConfig& config);

/// The map server's parameters (the map file may come as the nodelet's first argument instead).
struct MapServerConfig {
  std::string map_file;
  std::string map_frame = "map";  ///< frame of the published map (was frame_id)

  std::string validate() const;
};

void readMapServerConfig(wheelchair_core::ConfigReader& reader, MapServerConfig& config);

/// The obstacle layer nodelet's parameters: the layer's and the node's own.
struct ObstacleLayerNodeConfig {
  ObstacleLayerConfig layer;
  std::string map_frame = "map";  ///< frame of /map, where the laser pose is looked up
  double tf_timeout = 0.1;        ///< [s] wait for the laser pose at a scan's stamp
  double publish_period = 0.2;    ///< [s] /obstacles when it changed (the decay included)
  /// Fuse scans only while /localization/status says localized (a guessed pose would put
  /// obstacles where there are none); false for a pose from elsewhere (the simulator's truth).
  bool require_localized = true;

  std::string validate() const;
};

void readObstacleLayerNodeConfig(wheelchair_core::ConfigReader& reader,
                                 ObstacleLayerNodeConfig& config);

}  // namespace wheelchair_mapping
