// rostest: the simulator nodelet refuses to start on a misspelt key, the old chair_config key
// or an invalid value (nodelet::Loader::load fails, so rosrun exits), and starts on the keys
// the tests pass today, sim.yaml's overridden one by one.
#include <gtest/gtest.h>
#include <nodelet/loader.h>
#include <ros/ros.h>

#include <map>
#include <string>

namespace {

std::string world;  ///< the test's ~world

/// Loads the simulator as nodelet `name` with `params` (and ~world) as its private ones.
bool loads(const std::string& name, const std::map<std::string, XmlRpc::XmlRpcValue>& params) {
  ros::param::set(name + "/world", world);
  for (const auto& [key, value] : params) ros::param::set(name + "/" + key, value);
  static nodelet::Loader loader(false);
  const bool loaded = loader.load(name, "wheelchair_sim/SimulatorNodelet", {}, {});
  if (loaded) loader.unload(name);
  return loaded;
}

TEST(RefusedParameters, TheTestsKeysLoad) {
  EXPECT_TRUE(loads("/good_sim", {{"speed", 10.0},
                                  {"rolling_resistance", false},
                                  {"odom_noise", 0.0},
                                  {"laser_range_noise", 0.01},
                                  {"publish_laser_tf", true},
                                  {"initial_x", 1.0}}));
}

TEST(RefusedParameters, AMisspeltKeyRefusesTheSimulator) {
  EXPECT_FALSE(loads("/misspelt_sim", {{"laser_rte", 5.0}}));
}

TEST(RefusedParameters, TheOldChairConfigKeyRefusesTheSimulator) {
  EXPECT_FALSE(loads("/old_key_sim", {{"chair_config", std::string("chair.yaml")}}));
}

TEST(RefusedParameters, AnInvalidValueRefusesTheSimulator) {
  EXPECT_FALSE(loads("/slow_sim", {{"physics_rate", 100.0}}));
  EXPECT_FALSE(loads("/bus_sim", {{"motor_bus", std::string("can")}}));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_refused_parameters");
  ros::NodeHandle pnh("~");
  pnh.getParam("world", world);
  return RUN_ALL_TESTS();
}
