// The base driver nodelet's keys, read from a YAML source as the nodelet reads its private
// parameters: the bring-up files' keys are known, the chair's values are the defaults, an old
// or misspelt key and an invalid value are refused with a sentence naming them.
#include <wheelchair_base_driver/base_driver_settings.h>
#include <wheelchair_core/config.h>
#include <yaml-cpp/yaml.h>

#include <gtest/gtest.h>

#include <string>

namespace wheelchair_base_driver {
namespace {

BaseDriverSettings chairDefaults() {
  BaseDriverSettings s;
  s.driver.geometry.wheel_radius = 0.17;
  s.driver.geometry.half_track = 0.275;
  s.driver.max_torque = 50.0;
  s.driver.max_speed = 1.5;
  return s;
}

BaseDriverSettings load(const std::string& yaml) {
  return wheelchair_core::loadConfig<BaseDriverSettings>(
      wheelchair_core::YamlParameterSource(YAML::Load(yaml), "/base_driver"),
      readBaseDriverSettings, chairDefaults());
}

std::string errorOf(const std::string& yaml) {
  try {
    load(yaml);
  } catch (const wheelchair_core::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Settings, TheDefaultsAreTheStructsAndTheChairs) {
  const BaseDriverSettings s = load("");
  EXPECT_EQ(s.transport.kind, "socketcan");
  EXPECT_EQ(s.transport.interface, "can0");
  EXPECT_EQ(s.transport.udp_local_port, 47110);
  EXPECT_EQ(s.transport.udp_remote_port, 47111);
  EXPECT_DOUBLE_EQ(s.driver.geometry.counts_per_rev, 4096.0);
  EXPECT_DOUBLE_EQ(s.driver.command_period, 0.01);
  EXPECT_DOUBLE_EQ(s.driver.command_timeout, 0.1);
  EXPECT_DOUBLE_EQ(s.driver.controller_timeout, 0.2);
  EXPECT_DOUBLE_EQ(s.driver.max_torque, 50.0);  // the chair's max_wheel_torque
  EXPECT_DOUBLE_EQ(s.driver.max_speed, 1.5);    // the chair's max_speed
  EXPECT_DOUBLE_EQ(s.driver.permit_timeout, 0.1);
  EXPECT_DOUBLE_EQ(s.driver.stop_window, 4.0);
  EXPECT_DOUBLE_EQ(s.driver.speed_limit_decel, 0.5);
  EXPECT_DOUBLE_EQ(s.driver.speed_limit_tolerance, 0.05);
  EXPECT_DOUBLE_EQ(s.driver.controller_wall_timeout, 1.0);
  EXPECT_EQ(s.odom_frame, "odom");
  EXPECT_EQ(s.base_frame, "base_link");
  EXPECT_EQ(s.left_wheel_joint, "left_wheel_joint");
  EXPECT_DOUBLE_EQ(s.spin_rate, 100.0);
  EXPECT_DOUBLE_EQ(s.odom_rate, 0.0);
}

TEST(Settings, TheHardwareBringUpKeysAreRead) {
  const BaseDriverSettings s = load(
      "transport: socketcan\ninterface: can1\ncan_bitrate: 500000\nodom_frame: odom\n"
      "base_frame: base_link\npublish_tf: false\nspin_rate: 100.0\nodom_rate: 50.0\n"
      "command_rate: 50\nmax_torque: 30\ncounts_per_rev: 2048\n");
  EXPECT_EQ(s.transport.interface, "can1");
  EXPECT_FALSE(s.publish_tf);
  EXPECT_DOUBLE_EQ(s.odom_rate, 50.0);
  EXPECT_DOUBLE_EQ(s.driver.command_period, 0.02);
  EXPECT_DOUBLE_EQ(s.driver.max_torque, 30.0);
  EXPECT_DOUBLE_EQ(s.driver.geometry.counts_per_rev, 2048.0);
}

TEST(Settings, ChairParamsIsRefusedNamingChairFile) {
  const std::string e = errorOf("chair_params: chair.yaml");
  EXPECT_NE(e.find("'chair_params' is now called 'chair_file'"), std::string::npos) << e;
}

TEST(Settings, AMisspeltKeyIsRefusedWithTheKnownKeys) {
  const std::string e = errorOf("comand_timeout: 0.1");
  EXPECT_NE(e.find("/base_driver: unknown parameter 'comand_timeout'"), std::string::npos) << e;
  EXPECT_NE(e.find("command_timeout"), std::string::npos) << e;
}

TEST(Settings, InvalidValuesAreRefused) {
  EXPECT_NE(errorOf("transport: can").find("unknown transport 'can'"), std::string::npos);
  EXPECT_NE(errorOf("udp_local_port: 70000").find("UDP ports"), std::string::npos);
  EXPECT_NE(errorOf("command_timeout: 0").find("command_timeout must be positive"),
            std::string::npos);
  EXPECT_NE(errorOf("max_torque: 400").find("327.67"), std::string::npos);
  EXPECT_NE(errorOf("odom_rate: -1").find("odom_rate"), std::string::npos);
  EXPECT_NE(errorOf("permit_timeout: 0").find("permit_timeout must be positive"),
            std::string::npos);
  EXPECT_NE(errorOf("max_speed: -1").find("max_speed"), std::string::npos);
  EXPECT_NE(errorOf("speed_limit_decel: 0").find("speed_limit_decel must be positive"),
            std::string::npos);
  EXPECT_NE(errorOf("speed_limit_tolerance: -0.1").find("speed_limit_tolerance"),
            std::string::npos);
}

}  // namespace
}  // namespace wheelchair_base_driver
