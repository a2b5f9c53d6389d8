// The navigator nodelet's one loader, from YAML (the same reader as the ROS parameters): every
// key read, the defaults kept, unknown and renamed keys and unusable values refused.
#include "navigator_parameters.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

namespace wheelchair_navigator {
namespace {

NavigatorParameters load(const std::string& yaml) {
  const wheelchair_core::YamlParameterSource source(YAML::Load(yaml), "test");
  return wheelchair_core::loadConfig<NavigatorParameters>(source, readNavigatorParameters);
}

TEST(NavigatorParameters, DefaultsAreTheStructsOwn) {
  const NavigatorParameters p = load("{}");
  const NavigatorParameters defaults;
  EXPECT_EQ(p.map_frame, "map");
  EXPECT_EQ(p.planner_service, "planner/make_plan");
  EXPECT_EQ(p.navigator.wait_for_clear, defaults.navigator.wait_for_clear);
  EXPECT_EQ(p.navigator.max_control_retries, 2);
}

TEST(NavigatorParameters, EveryKeyIsRead) {
  const NavigatorParameters p = load(
      "{map_frame: world, base_frame: chair, chair_file: /c.yaml, places_file: /p.yaml, "
      "rate: 5.0, planner_service: /p/make, controller_path_status: /c/s, planner_timeout: 9, "
      "safety_clear_timeout: 3, max_planner_retries: 0, retry_delay: 2, wait_for_clear: 4, "
      "probe_period: 0.5, clear_confirm: 2, blocked_timeout: 30, replan_period: 3, "
      "max_replans: 4, block_start: 0.4, block_length: 1.4, block_clearance: 0.2, "
      "where_radius: 2, start_tolerance: 0.2, layer_lookahead: 2, layer_corridor: 0.4, "
      "layer_max_age: 1, "
      "no_progress_timeout: 20, progress_distance: 0.2, progress_rotation: 0.4, "
      "max_control_retries: 1, stop_timeout: 4, max_back_ups: 0, goal_min_clearance: 0.02}");
  EXPECT_EQ(p.map_frame, "world");
  EXPECT_EQ(p.places_file, "/p.yaml");
  EXPECT_EQ(p.rate, 5.0);
  EXPECT_EQ(p.navigator.wait_for_clear, 4.0);
  EXPECT_EQ(p.navigator.max_replans, 4);
  EXPECT_EQ(p.navigator.goal_min_clearance, 0.02);
  EXPECT_EQ(p.navigator.max_back_ups, 0);
  EXPECT_EQ(p.navigator.start_tolerance, 0.2);
}

TEST(NavigatorParameters, UnknownRenamedAndUnusableKeysAreRefused) {
  EXPECT_THROW(load("{wait_for_clearr: 3}"), wheelchair_core::ConfigError);
  try {
    load("{global_frame: map}");
    FAIL() << "the old name was accepted";
  } catch (const wheelchair_core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("map_frame"), std::string::npos) << e.what();
  }
  EXPECT_THROW(load("{probe_period: 0}"), wheelchair_core::ConfigError);
  EXPECT_THROW(load("{block_start: 2.0, block_length: 1.0}"), wheelchair_core::ConfigError);
  EXPECT_THROW(load("{max_replans: -1}"), wheelchair_core::ConfigError);
  EXPECT_THROW(load("{rate: -1}"), wheelchair_core::ConfigError);
  EXPECT_THROW(load("{start_tolerance: 0}"), wheelchair_core::ConfigError);
}

}  // namespace
}  // namespace wheelchair_navigator
