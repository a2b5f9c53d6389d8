// The mapper's and the mapping nodelets' one parameter list: every key read, defaults valid,
// unknown / renamed keys and invalid values refused with a message that names them.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

#include "mapping_node_config.h"

namespace wheelchair_mapping {
namespace {

using wheelchair_core::ConfigError;
using wheelchair_core::YamlParameterSource;

template <typename Config, typename Read>
std::string errorOf(const std::string& yaml, Read read) {
  try {
    wheelchair_core::loadConfig<Config>(YamlParameterSource(YAML::Load(yaml), "test.yaml"), read);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(MappingParams, TheDefaultsAreValid) {
  EXPECT_EQ(MapperConfig().validate(), "");
  EXPECT_EQ(MappingNodeConfig().validate(), "");
  EXPECT_EQ(MapServerConfig().validate(), "");
}

TEST(MappingParams, EveryKeyOfTheMappingNodeIsRead) {
  const auto c = wheelchair_core::loadConfig<MappingNodeConfig>(
      YamlParameterSource(YAML::Load("{resolution: 0.1, expected_beams: 361, p_occ_hit: 0.8,"
                                     " beam_width: 0.01, hit_depth: 0.01, no_return_is_free: false,"
                                     " map_frame: map, publish_period: 0.5, save_path: a.yaml}"),
                          "test.yaml"),
      readMappingNodeConfig);
  EXPECT_DOUBLE_EQ(c.mapper.resolution, 0.1);
  EXPECT_EQ(c.mapper.expected_beams, 361);
  EXPECT_DOUBLE_EQ(c.mapper.model.p_occ_hit, 0.8);
  EXPECT_DOUBLE_EQ(c.mapper.model.beam_width, 0.01);
  EXPECT_DOUBLE_EQ(c.mapper.model.hit_depth, 0.01);
  EXPECT_FALSE(c.mapper.model.no_return_is_free);
  EXPECT_EQ(c.map_frame, "map");
  EXPECT_DOUBLE_EQ(c.publish_period, 0.5);
  EXPECT_EQ(c.save_path, "a.yaml");
  EXPECT_DOUBLE_EQ(c.tf_timeout, MappingNodeConfig().tf_timeout);
}

TEST(MappingParams, OldFrameNamesAreRefusedNamingTheNewOne) {
  EXPECT_NE(errorOf<MappingNodeConfig>("{pose_frame: odom}", readMappingNodeConfig)
                .find("'pose_frame' is now called 'map_frame'"),
            std::string::npos);
  EXPECT_NE(errorOf<MapServerConfig>("{frame_id: map}", readMapServerConfig)
                .find("'frame_id' is now called 'map_frame'"),
            std::string::npos);
}

TEST(MappingParams, UnknownKeysAndInvalidValuesAreRefused) {
  const std::string unknown = errorOf<MappingNodeConfig>("{p_hit: 0.7}", readMappingNodeConfig);
  EXPECT_NE(unknown.find("unknown parameter 'p_hit'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("p_occ_hit"), std::string::npos) << unknown;
  EXPECT_NE(errorOf<MappingNodeConfig>("{p_occ_hit: 0.4}", readMappingNodeConfig)
                .find("p_occ_hit must be in (0.5, 1)"),
            std::string::npos);
  EXPECT_NE(errorOf<MappingNodeConfig>("{resolution: 0}", readMappingNodeConfig)
                .find("resolution must be positive"),
            std::string::npos);
  EXPECT_NE(errorOf<MappingNodeConfig>("{expected_beams: -1}", readMappingNodeConfig)
                .find("expected_beams"),
            std::string::npos);
  EXPECT_NE(errorOf<MapServerConfig>("{map_file: a.yaml, map_frame: ''}", readMapServerConfig)
                .find("map_frame must be named"),
            std::string::npos);
}

}  // namespace
}  // namespace wheelchair_mapping

namespace wheelchair_mapping {
namespace {

TEST(ObstacleLayerParams, EveryKeyIsReadAndUnknownOrInvalidOnesAreRefused) {
  EXPECT_EQ(ObstacleLayerNodeConfig().validate(), "");
  const auto c = wheelchair_core::loadConfig<ObstacleLayerNodeConfig>(
      YamlParameterSource(YAML::Load("{p_occ_hit: 0.75, p_occ_pass: 0.3, max_insertion_range: 6,"
                                     " no_return_is_free: false, no_return_range: 4,"
                                     " obstacle_probability: 0.7, max_probability: 0.95,"
                                     " forget_time: 3, map_margin: 0.15, map_frame: world,"
                                     " tf_timeout: 0.2, publish_period: 0.5,"
                                     " require_localized: false}"),
                          "test.yaml"),
      readObstacleLayerNodeConfig);
  EXPECT_DOUBLE_EQ(c.layer.model.p_occ_hit, 0.75);
  EXPECT_DOUBLE_EQ(c.layer.model.p_occ_pass, 0.3);
  EXPECT_DOUBLE_EQ(c.layer.model.max_insertion_range, 6.0);
  EXPECT_FALSE(c.layer.model.no_return_is_free);
  EXPECT_DOUBLE_EQ(c.layer.model.no_return_range, 4.0);
  EXPECT_DOUBLE_EQ(c.layer.obstacle_probability, 0.7);
  EXPECT_DOUBLE_EQ(c.layer.max_probability, 0.95);
  EXPECT_DOUBLE_EQ(c.layer.forget_time, 3.0);
  EXPECT_DOUBLE_EQ(c.layer.map_margin, 0.15);
  EXPECT_EQ(c.map_frame, "world");
  EXPECT_DOUBLE_EQ(c.tf_timeout, 0.2);
  EXPECT_DOUBLE_EQ(c.publish_period, 0.5);
  EXPECT_FALSE(c.require_localized);
  const std::string unknown =
      errorOf<ObstacleLayerNodeConfig>("{decay: 3}", readObstacleLayerNodeConfig);
  EXPECT_NE(unknown.find("decay"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("forget_time"), std::string::npos) << unknown;
  const std::string invalid =
      errorOf<ObstacleLayerNodeConfig>("{forget_time: 0}", readObstacleLayerNodeConfig);
  EXPECT_NE(invalid.find("forget_time"), std::string::npos) << invalid;
}

}  // namespace
}  // namespace wheelchair_mapping
