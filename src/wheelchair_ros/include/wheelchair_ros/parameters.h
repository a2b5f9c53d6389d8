// The ROS side of the one parameter pattern (wheelchair_core/config.h): a nodelet's private
// parameters as a ParameterSource, and the nodelet's loader. A nodelet calls
//   config_ = wheelchair_ros::loadParameters<Config>(getPrivateNodeHandle(), readConfig);
// in onInit(); an unknown or renamed key or an invalid value throws ConfigError, the nodelet
// loader then refuses to load the nodelet (nodelet::Loader::load returns false and logs the
// message), and `rosrun` / the chair process exit with that message.
#pragma once

#include <ros/node_handle.h>
#include <wheelchair_core/config.h>

#include <string>
#include <vector>

namespace wheelchair_ros {

/// The parameters under a node handle's namespace (a nodelet's private namespace).
class RosParameterSource : public wheelchair_core::ParameterSource {
 public:
  explicit RosParameterSource(const ros::NodeHandle& nh);

  std::vector<std::string> keys() const override;
  bool get(const std::string& key, bool& value) const override;
  bool get(const std::string& key, int& value) const override;
  bool get(const std::string& key, double& value) const override;
  bool get(const std::string& key, std::string& value) const override;
  bool get(const std::string& key, std::vector<double>& value) const override;
  bool get(const std::string& key, std::vector<std::string>& value) const override;
  bool get(const std::string& key, std::vector<Eigen::Vector2d>& value) const override;
  std::string where() const override { return nh_.getNamespace(); }

 private:
  ros::NodeHandle nh_;
};

/// wheelchair_core::loadConfig on the private parameters of `nh`, logging what was refused.
/// Throws wheelchair_core::ConfigError.
template <typename Config, typename ReadKeys>
Config loadParameters(const ros::NodeHandle& nh, ReadKeys&& read_keys, Config config = Config()) {
  const RosParameterSource source(nh);
  try {
    return wheelchair_core::loadConfig<Config>(source, read_keys, std::move(config));
  } catch (const wheelchair_core::ConfigError& e) {
    ROS_FATAL("%s", e.what());
    throw;
  }
}

}  // namespace wheelchair_ros
