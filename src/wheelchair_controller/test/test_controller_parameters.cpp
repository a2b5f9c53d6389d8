// The controller's one parameter loader: every key it reads, the old name of the chair file
// refused with the new one, an unknown key refused with the known ones, an invalid value refused.
#include "../src/nodelet/controller_parameters.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

namespace wc = wheelchair_controller;
using wheelchair_core::ConfigError;

namespace {

/// The parameters of a YAML mapping, loaded as the nodelet loads its private namespace.
wc::ControllerParameters load(const std::string& yaml) {
  const wheelchair_core::YamlParameterSource source(YAML::Load(yaml), "test");
  return wheelchair_core::loadConfig<wc::ControllerParameters>(source,
                                                               wc::readControllerParameters);
}

std::string refusal(const std::string& yaml) {
  try {
    load(yaml);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ControllerParameters, EveryKeyFillsItsField) {
  const wc::ControllerParameters p = load(
      "{chair_file: /tmp/chair.yaml, map_frame: world, base_frame: base, rate: 25,"
      " natural_frequency: 2.0, damping: 0.8, max_speed: 0.6, max_accel: 0.4, max_jerk: 0.9,"
      " stale_pose_timeout: 0.5, stale_odometry_timeout: 0.4, pose_jump: 0.3,"
      " dynamic_terms: false, reverse_lookahead: 0.2, reverse_max_speed: 0.25}");
  EXPECT_EQ(p.chair_file, "/tmp/chair.yaml");
  EXPECT_EQ(p.map_frame, "world");
  EXPECT_EQ(p.base_frame, "base");
  EXPECT_DOUBLE_EQ(p.rate, 25.0);
  EXPECT_DOUBLE_EQ(p.tracker.natural_frequency, 2.0);
  EXPECT_DOUBLE_EQ(p.tracker.damping, 0.8);
  EXPECT_DOUBLE_EQ(p.tracker.path_limits.longitudinal.speed, 0.6);
  EXPECT_DOUBLE_EQ(p.tracker.path_limits.longitudinal.accel, 0.4);
  EXPECT_DOUBLE_EQ(p.tracker.path_limits.longitudinal.jerk, 0.9);
  EXPECT_DOUBLE_EQ(p.tracker.stop.linear.accel, 0.4) << "a stop brakes within the path's limits";
  EXPECT_DOUBLE_EQ(p.tracker.stop.linear.jerk, 0.9);
  EXPECT_DOUBLE_EQ(p.tracker.stale_pose_timeout, 0.5);
  EXPECT_DOUBLE_EQ(p.tracker.stale_odometry_timeout, 0.4);
  EXPECT_DOUBLE_EQ(p.tracker.pose_jump, 0.3);
  EXPECT_FALSE(p.tracker.dynamic_terms);
  EXPECT_DOUBLE_EQ(p.tracker.reverse_lookahead, 0.2);
  EXPECT_DOUBLE_EQ(p.tracker.reverse_max_speed, 0.25);
}

TEST(ControllerParameters, DefaultsAreTheTrackersOwn) {
  const wc::ControllerParameters p = load("{}");
  const wc::TrackerConfig defaults;
  EXPECT_DOUBLE_EQ(p.tracker.natural_frequency, defaults.natural_frequency);
  EXPECT_DOUBLE_EQ(p.tracker.stop.linear.accel, defaults.stop.linear.accel);
  EXPECT_DOUBLE_EQ(p.rate, 50.0);
  EXPECT_FALSE(p.chair_file.empty());
}

TEST(ControllerParameters, RefusesTheOldChairKeyAnUnknownKeyAndAnInvalidValue) {
  EXPECT_NE(refusal("{chair_params: /tmp/chair.yaml}").find("now called 'chair_file'"),
            std::string::npos);
  const std::string unknown = refusal("{natural_frequncy: 2.0}");
  EXPECT_NE(unknown.find("unknown parameter 'natural_frequncy'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("natural_frequency"), std::string::npos) << "names the known keys";
  EXPECT_NE(refusal("{rate: 0}").find("rate must be positive"), std::string::npos);
  // Reverse faster than 0.3 m/s is refused (issue 24: backing up sees less and steers with the
  // tail).
  EXPECT_NE(refusal("{reverse_max_speed: 0.5}").find("reverse_max_speed"), std::string::npos);
  EXPECT_NE(refusal("{max_accel: -0.5}").find("path accel must be positive"), std::string::npos);
  EXPECT_NE(refusal("{dynamic_terms: often}").find("dynamic_terms"), std::string::npos);
}
