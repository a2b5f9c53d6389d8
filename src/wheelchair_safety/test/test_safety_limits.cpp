// The supervisor's limits through the one parameter pattern: defaults, every key, refusals.
#include <wheelchair_safety/safety_limits.h>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

using wheelchair_core::ConfigError;
using wheelchair_core::loadConfig;
using wheelchair_core::YamlParameterSource;
using wheelchair_safety::readSafetyLimits;
using wheelchair_safety::SafetyLimits;

namespace {

SafetyLimits fromYaml(const std::string& text) {
  return loadConfig<SafetyLimits>(YamlParameterSource(YAML::Load(text), "test.yaml"),
                                  readSafetyLimits);
}

std::string refusal(const std::string& text) {
  try {
    fromYaml(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SafetyLimits, DefaultsAreValid) { EXPECT_EQ(SafetyLimits().validate(), ""); }

TEST(SafetyLimits, EveryKeyIsRead) {
  const SafetyLimits l = fromYaml(
      "{scan_timeout: 1.5, pose_timeout: 1.4, localization_timeout: 3, max_position_std: 0.3, "
      "max_heading_std: 0.25, stop_distance: 2.0, corridor_half_width: 0.5, map_tolerance: 0.1, "
      "min_obstacle_returns: 5, driver_fault_grace: 0.5, rear_scan_timeout: 0.4, "
      "rear_stop_distance: 0.7, rear_overhang: 0.9}");
  EXPECT_DOUBLE_EQ(l.scan_timeout, 1.5);
  EXPECT_DOUBLE_EQ(l.pose_timeout, 1.4);
  EXPECT_DOUBLE_EQ(l.localization_timeout, 3.0);
  EXPECT_DOUBLE_EQ(l.max_position_std, 0.3);
  EXPECT_DOUBLE_EQ(l.max_heading_std, 0.25);
  EXPECT_DOUBLE_EQ(l.stop_distance, 2.0);
  EXPECT_DOUBLE_EQ(l.corridor_half_width, 0.5);
  EXPECT_DOUBLE_EQ(l.map_tolerance, 0.1);
  EXPECT_EQ(l.min_obstacle_returns, 5);
  EXPECT_DOUBLE_EQ(l.driver_fault_grace, 0.5);
  EXPECT_DOUBLE_EQ(l.rear_scan_timeout, 0.4);
  EXPECT_DOUBLE_EQ(l.rear_stop_distance, 0.7);
  EXPECT_DOUBLE_EQ(l.rear_overhang, 0.9);
}

TEST(SafetyLimits, AMisspeltKeyIsRefusedWithTheKnownKeys) {
  const std::string why = refusal("{scan_timout: 0.5}");
  EXPECT_NE(why.find("unknown parameter 'scan_timout'"), std::string::npos) << why;
  EXPECT_NE(why.find("scan_timeout"), std::string::npos) << why;
}

TEST(SafetyLimits, AnUnusableLimitIsRefusedWithItsName) {
  EXPECT_NE(refusal("{scan_timeout: 0.0}").find("scan_timeout must be positive"),
            std::string::npos);
  EXPECT_NE(refusal("{min_obstacle_returns: 0}").find("min_obstacle_returns"), std::string::npos);
  EXPECT_NE(refusal("{map_tolerance: -0.1}").find("map_tolerance"), std::string::npos);
  EXPECT_NE(refusal("{stop_distance: fast}").find("must be a number"), std::string::npos);
}
