// rostest: the driver nodelet refuses to start on a misspelt key, an old key name or an invalid
// value (nodelet::Loader::load fails, so rosrun and the chair process exit), and starts on a
// good configuration. A misspelt watchdog must never fall back silently to a default.
#include <gtest/gtest.h>
#include <nodelet/loader.h>
#include <ros/ros.h>

#include <map>
#include <string>

namespace {

/// Loads the driver as nodelet `name` with `params` (and transport fake) as its private ones.
bool loads(const std::string& name, const std::map<std::string, XmlRpc::XmlRpcValue>& params) {
  ros::param::set(name + "/transport", std::string("fake"));
  ros::param::set(name + "/fake_bus", name);  // a bus of its own
  for (const auto& [key, value] : params) ros::param::set(name + "/" + key, value);
  static nodelet::Loader loader(false);
  const bool loaded = loader.load(name, "wheelchair_base_driver/BaseDriverNodelet", {}, {});
  if (loaded) loader.unload(name);
  return loaded;
}

TEST(RefusedParameters, AGoodConfigurationLoads) {
  EXPECT_TRUE(loads("/good_driver", {{"command_timeout", 0.1}, {"odom_rate", 50.0}}));
}

TEST(RefusedParameters, AMisspeltKeyRefusesTheDriver) {
  EXPECT_FALSE(loads("/misspelt_driver", {{"comand_timeout", 0.1}}));
}

TEST(RefusedParameters, TheOldChairParamsKeyRefusesTheDriver) {
  EXPECT_FALSE(loads("/old_key_driver", {{"chair_params", std::string("chair.yaml")}}));
}

TEST(RefusedParameters, AnInvalidValueRefusesTheDriver) {
  EXPECT_FALSE(loads("/invalid_driver", {{"controller_timeout", -0.2}}));
  EXPECT_FALSE(loads("/wrong_type_driver", {{"command_timeout", std::string("fast")}}));
}

// The drive channel has one driver per process: a second one (another nodelet loaded into the
// chair's manager) would be a second path to the motors.
TEST(RefusedParameters, ASecondDriverInTheProcessIsRefused) {
  ros::param::set("/first_driver/transport", std::string("fake"));
  ros::param::set("/first_driver/fake_bus", std::string("first_driver"));
  static nodelet::Loader loader(false);
  ASSERT_TRUE(loader.load("/first_driver", "wheelchair_base_driver/BaseDriverNodelet", {}, {}));
  EXPECT_FALSE(loads("/second_driver", {}));
  loader.unload("/first_driver");
  EXPECT_TRUE(loads("/third_driver", {})) << "the role is free again once the first is unloaded";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_refused_parameters");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
