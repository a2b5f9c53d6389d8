// The simulator nodelet's keys, read from a YAML source as the nodelet reads its private
// parameters: every key is known, sim.yaml's values are overridden one by one, an old or
// misspelt key and an invalid value are refused with a sentence naming them.
#include <wheelchair_core/config.h>
#include <wheelchair_sim/simulator_settings.h>
#include <yaml-cpp/yaml.h>

#include <gtest/gtest.h>

#include <string>

namespace wheelchair_sim {
namespace {

SimulatorSettings load(const std::string& yaml, SimulatorSettings defaults = {}) {
  return wheelchair_core::loadConfig<SimulatorSettings>(
      wheelchair_core::YamlParameterSource(YAML::Load(yaml), "/simulator"), readSimulatorSettings,
      defaults);
}

std::string errorOf(const std::string& yaml) {
  try {
    load(yaml);
  } catch (const wheelchair_core::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Settings, TheTestsKeysAreReadAndOverrideTheFilesValues) {
  SimulatorSettings file_values;
  file_values.sim.laser_range_noise = 0.01;
  file_values.sim.rolling_resistance = true;
  const SimulatorSettings s = load(
      "world: room.yaml\nspeed: 2\ninitial_x: 3.0\ninitial_y: 4.7\ninitial_yaw: 1.5707963\n"
      "publish_laser_tf: true\npublish_odometry: false\nlaser_range_noise: 0.0\n"
      "motor_bus: udp\nudp_local_port: 47211\nudp_remote_port: 47210\ncounts_per_rev: 2048\n",
      file_values);
  EXPECT_EQ(s.world, "room.yaml");
  EXPECT_DOUBLE_EQ(s.speed, 2.0);
  EXPECT_DOUBLE_EQ(s.initial.x, 3.0);
  EXPECT_DOUBLE_EQ(s.initial.y, 4.7);
  EXPECT_DOUBLE_EQ(s.initial.yaw, 1.5707963);
  EXPECT_TRUE(s.publish_laser_tf);
  EXPECT_FALSE(s.publish_odometry);
  EXPECT_EQ(s.sim.laser_range_noise, 0.0);  // overridden
  EXPECT_TRUE(s.sim.rolling_resistance);    // the file's value stays
  EXPECT_EQ(s.motor_bus, "udp");
  EXPECT_EQ(s.udp_local_port, 47211);
  EXPECT_EQ(s.udp_remote_port, 47210);
  EXPECT_DOUBLE_EQ(s.motor_controller.counts_per_rev, 2048.0);
  EXPECT_EQ(s.map_frame, "map");
  EXPECT_EQ(s.base_frame, "base_link");
  EXPECT_EQ(s.laser_frame, "laser");
}

TEST(Settings, TheWorldIsRequired) {
  EXPECT_NE(errorOf("speed: 1").find("missing parameter 'world'"), std::string::npos);
}

TEST(Settings, ChairConfigIsRefusedNamingChairFile) {
  const std::string e = errorOf("world: w.yaml\nchair_config: c.yaml");
  EXPECT_NE(e.find("'chair_config' is now called 'chair_file'"), std::string::npos) << e;
}

TEST(Settings, AMisspeltKeyIsRefusedWithTheKnownKeys) {
  const std::string e = errorOf("world: w.yaml\nlaser_rte: 5");
  EXPECT_NE(e.find("unknown parameter 'laser_rte'"), std::string::npos) << e;
  EXPECT_NE(e.find("laser_rate"), std::string::npos) << e;
}

TEST(Settings, ObstaclesAreAllowedForTheNodeletToRead) {
  EXPECT_EQ(errorOf("world: w.yaml\nobstacles: [{x: 1.0, y: 2.0}]"), "");
}

TEST(Settings, InvalidValuesAreRefused) {
  EXPECT_NE(errorOf("world: w.yaml\nmotor_bus: can").find("unknown motor_bus 'can'"),
            std::string::npos);
  EXPECT_NE(errorOf("world: w.yaml\nstep: 0").find("step must be positive"), std::string::npos);
  EXPECT_NE(errorOf("world: w.yaml\nphysics_rate: 100").find("physics_rate"), std::string::npos);
  EXPECT_NE(errorOf("world: w.yaml\nudp_local_port: 70000").find("UDP ports"), std::string::npos);
}

}  // namespace
}  // namespace wheelchair_sim
