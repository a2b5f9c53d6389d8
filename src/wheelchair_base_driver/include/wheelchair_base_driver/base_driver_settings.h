// Every key of the base driver nodelet, in one struct: the driver core's (DriverConfig), the
// transport's (TransportOptions) and the node's own (frames, joints, rates, the stand-alone
// emulated controller). Defaults here only; the nodelet reads them all with
//   wheelchair_ros::loadParameters(private_nh, readBaseDriverSettings, chair_defaults)
// where chair_defaults carries the chair file's wheel geometry and torque limit.
#pragma once

#include <wheelchair_base_driver/driver_config.h>
#include <wheelchair_base_driver/transport_factory.h>
#include <wheelchair_description/urdf_generator.h>

#include <string>

namespace wheelchair_core {
class ConfigReader;
}

namespace wheelchair_base_driver {

struct BaseDriverSettings {
  /// The chair's description (wheel radius, half track, max_wheel_torque); "" = the one of
  /// wheelchair_description, found at run time.
  std::string chair_file;
  DriverConfig driver;
  TransportOptions transport;
  /// Transport `fake` only: host an emulated motor controller with a trivial wheel plant.
  bool emulate_controller = true;
  double emulated_wheel_inertia = 2.0;  ///< [kg m^2] of the trivial plant's wheels
  double emulated_wheel_damping = 4.0;  ///< [N m s] of the trivial plant's wheels
  std::string odom_frame = "odom";
  std::string base_frame = "base_link";
  std::string left_wheel_joint = wheelchair_description::kLeftWheelJoint;
  std::string right_wheel_joint = wheelchair_description::kRightWheelJoint;
  bool publish_tf = true;  ///< tf odom -> base_link with every /odom
  /// [Hz] bus poll, watchdogs and command sending: 100 Hz = the command rate, so a 100 ms
  /// watchdog fires within 10 ms of its deadline (500 Hz cost 5x the CPU for nothing).
  double spin_rate = 100.0;
  /// [Hz] most /odom, tf and /joint_states per second; 0 = on every encoder frame (each one
  /// wakes every tf listener and the description publisher of the process).
  double odom_rate = 0.0;

  /// "" if usable, else every problem (the driver's and the transport's included).
  std::string validate() const;
};

/// Every key above (chair_file, the DriverConfig and TransportOptions keys, the node's own);
/// `chair_params` is refused as renamed; `can_bitrate` (read by deploy/can-up), `udp_bound_port`
/// (written by the nodelet) and `diagnostic_period` (read by diagnostic_updater) are allowed.
void readBaseDriverSettings(wheelchair_core::ConfigReader& reader, BaseDriverSettings& settings);

}  // namespace wheelchair_base_driver
