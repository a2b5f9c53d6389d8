#include <wheelchair_base_driver/base_driver_settings.h>
#include <wheelchair_core/config.h>

namespace wheelchair_base_driver {

std::string BaseDriverSettings::validate() const {
  const std::string driver_problem = driver.validate();
  const std::string transport_problem = transport.validate();
  return wheelchair_core::ConfigChecks()
      .check(driver_problem.empty(), driver_problem)
      .check(transport_problem.empty(), transport_problem)
      .positive("emulated_wheel_inertia", emulated_wheel_inertia)
      .nonNegative("emulated_wheel_damping", emulated_wheel_damping)
      .check(!odom_frame.empty() && !base_frame.empty(), "frames must not be empty")
      .check(!left_wheel_joint.empty() && !right_wheel_joint.empty(),
             "joint names must not be empty")
      .positive("spin_rate", spin_rate)
      .nonNegative("odom_rate", odom_rate)
      .result();
}

void readBaseDriverSettings(wheelchair_core::ConfigReader& reader, BaseDriverSettings& settings) {
  reader.renamed("chair_params", "chair_file");
  reader.read("chair_file", settings.chair_file);
  readDriverConfig(reader, settings.driver);
  readTransportOptions(reader, settings.transport);
  reader.read("emulate_controller", settings.emulate_controller);
  reader.read("emulated_wheel_inertia", settings.emulated_wheel_inertia);
  reader.read("emulated_wheel_damping", settings.emulated_wheel_damping);
  reader.read("odom_frame", settings.odom_frame);
  reader.read("base_frame", settings.base_frame);
  reader.read("left_wheel_joint", settings.left_wheel_joint);
  reader.read("right_wheel_joint", settings.right_wheel_joint);
  reader.read("publish_tf", settings.publish_tf);
  reader.read("spin_rate", settings.spin_rate);
  reader.read("odom_rate", settings.odom_rate);
  reader.allow("can_bitrate");        // the CAN link's bitrate, set by deploy/can-up
  reader.allow("udp_bound_port");     // written by the nodelet: the port it bound
  reader.allow("diagnostic_period");  // diagnostic_updater's own
}

}  // namespace wheelchair_base_driver
