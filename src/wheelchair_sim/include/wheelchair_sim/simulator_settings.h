// Every key of the simulator nodelet, in one struct: the simulation's (SimParams, whose
// values come from sim.yaml and may be overridden one by one), the motor controller's when it
// plays the chair's CAN motor controller, and the node's own (world, pacing, start pose, frames,
// what it publishes). Defaults here only; the nodelet reads them all with
//   wheelchair_ros::loadParameters(private_nh, readSimulatorSettings, file_defaults)
// where file_defaults carries sim.yaml's SimParams and the chair's torque limit.
#pragma once

#include <wheelchair_can/emulated_motor_controller.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_description/urdf_generator.h>
#include <wheelchair_sim/sim_params.h>

#include <string>

namespace wheelchair_core {
class ConfigReader;
}

namespace wheelchair_sim {

struct SimulatorSettings {
  std::string world;       ///< map_server YAML of the ground truth (required)
  std::string chair_file;  ///< "" = wheelchair_description's chair.yaml, found at run time
  std::string sim_config;  ///< "" = this package's config/sim.yaml, found at run time
  SimParams sim;
  double speed = 1.0;               ///< simulated / wall time; 0 = as fast as possible
  double step = 0.005;              ///< [s] simulated time per loop and /clock tick
  double torque_timeout = 0.5;      ///< [s] simulated, without /wheel_torques -> zero torque
  wheelchair_core::Pose2D initial;  ///< keys initial_x, initial_y, initial_yaw
  bool publish_odometry = true;     ///< /odom and tf odom -> base_link (never on a motor bus)
  bool publish_laser_tf = false;    ///< static base_link -> laser, rear_laser (else the
                                    ///< description's)
  /// "" = torques from /wheel_torques; "udp" or "fake": play the chair's CAN motor controller
  /// on CAN over UDP (the base driver in another process) or on the fake bus of this process.
  std::string motor_bus;
  int udp_local_port = 47111;   ///< the motor controller's (the driver's udp_remote_port)
  int udp_remote_port = 47110;  ///< the driver's udp_local_port
  std::string fake_bus = "wheelchair_can";  ///< name of the process-wide fake bus
  wheelchair_can::EmulatedControllerConfig motor_controller;
  std::string map_frame = "map";
  std::string odom_frame = "odom";
  std::string base_frame = wheelchair_description::kBaseLinkFrame;
  std::string laser_frame = wheelchair_description::kLaserFrame;
  std::string rear_laser_frame = wheelchair_description::kRearLaserFrame;

  /// "" if usable, else every problem (the simulation's included).
  std::string validate() const;
};

/// Every key above, SimParams' by their names and counts_per_rev for the motor controller;
/// `chair_config` is refused as renamed; `obstacles` (a list of {x, y, radius, appear_time}, a
/// type no ParameterSource reads) is allowed and read by the nodelet.
void readSimulatorSettings(wheelchair_core::ConfigReader& reader, SimulatorSettings& settings);

}  // namespace wheelchair_sim
