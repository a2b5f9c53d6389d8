#include "mapping_node_config.h"

namespace wheelchair_mapping {

std::string MappingNodeConfig::validate() const {
  const std::string mapper_problem = mapper.validate();
  return wheelchair_core::ConfigChecks()
      .check(mapper_problem.empty(), mapper_problem)
      .check(!map_frame.empty(), "map_frame must be named")
      .nonNegative("tf_timeout", tf_timeout)
      .positive("publish_period", publish_period)
      .check(!save_path.empty(), "save_path must be named")
      .result();
}

void readMappingNodeConfig(wheelchair_core::ConfigReader& r, MappingNodeConfig& c) {
  readMapperConfig(r, c.mapper);
  r.renamed("pose_frame", "map_frame");
  r.read("map_frame", c.map_frame);
  r.read("tf_timeout", c.tf_timeout);
  r.read("publish_period", c.publish_period);
  r.read("save_path", c.save_path);
}

std::string MapServerConfig::validate() const {
  return wheelchair_core::ConfigChecks()
      .check(!map_frame.empty(), "map_frame must be named")
      .result();
}

void readMapServerConfig(wheelchair_core::ConfigReader& r, MapServerConfig& c) {
  r.renamed("frame_id", "map_frame");
  r.read("map_file", c.map_file);
  r.read("map_frame", c.map_frame);
}

std::string ObstacleLayerNodeConfig::validate() const {
  const std::string layer_problem = layer.validate();
  return wheelchair_core::ConfigChecks()
      .check(layer_problem.empty(), layer_problem)
      .check(!map_frame.empty(), "map_frame must be named")
      .nonNegative("tf_timeout", tf_timeout)
      .positive("publish_period", publish_period)
      .result();
}

void readObstacleLayerNodeConfig(wheelchair_core::ConfigReader& r, ObstacleLayerNodeConfig& c) {
  readObstacleLayerConfig(r, c.layer);
  r.read("map_frame", c.map_frame);
  r.read("tf_timeout", c.tf_timeout);
  r.read("publish_period", c.publish_period);
  r.read("require_localized", c.require_localized);
}

}  // namespace wheelchair_mapping
