// The simulator's own parameters (what the chair's YAML does not say: integration rate,
// disturbances, sensor models). One parameter pattern (wheelchair_core/config.h): defaults here
// (the paper's ideal model), validate(), the keys in readSimParams; config/sim.yaml (a
// realistic chair) is read with them, and the nodelet reads the same keys as private
// parameters over it.
#pragma once

#include <string>

namespace wheelchair_core {
class ConfigReader;
}

namespace wheelchair_sim {

struct SimParams {
  // Dynamics (all disturbances off = the paper's ideal model, eq. 15).
  double physics_rate = 1000.0;        ///< RK4 steps per simulated second [Hz], >= 500
  bool rolling_resistance = false;     ///< apply c_rr of the chair's YAML
  double resistance_smoothing = 0.05;  ///< wheel speed [rad/s] over which resistance fades to 0
  bool torque_limit = false;           ///< clamp commands to the chair's max_wheel_torque
  double brake_torque = 50.0;          ///< [N m] per wheel while the parking brake is requested
  double slip_noise = 0.0;             ///< wheel-ground slip [m per sqrt(m) rolled], per wheel
  // Laser (SICK-like, paper section 5: 361 readings over 180 deg).
  bool laser_enabled = true;
  double laser_rate = 10.0;  ///< [Hz]
  int laser_beams = 361;     ///< beams over the field of view, first and last included
  double laser_fov = 3.14159265358979323846;  ///< [rad]
  double laser_range_min = 0.05;              ///< [m]
  double laser_range_max = 30.0;              ///< [m]
  double laser_range_noise = 0.01;            ///< Gaussian range noise std [m]
  // Rear safety laser (nanoScan3 / TiM-S class, chair.yaml rear_laser: the 180 deg behind the
  // body): rate, range_min and noise as the front laser's.
  bool rear_laser_enabled = true;
  int rear_laser_beams = 361;
  double rear_laser_fov = 3.14159265358979323846;  ///< [rad]
  double rear_laser_range_max = 10.0;              ///< [m]
  // Wheel-encoder odometry errors.
  double odom_rate = 50.0;               ///< [Hz] of /odom and tf odom -> base_link
  double odom_radius_error_right = 0.0;  ///< relative error of the assumed right radius
  double odom_radius_error_left = 0.0;   ///< relative error of the assumed left radius
  double odom_track_error = 0.0;         ///< relative error of the assumed half track b
  double odom_noise = 0.0;               ///< random wheel-travel error [m per sqrt(m)]
  int seed = 1;                          ///< seed of every random generator of the run

  /// "" if usable, else every problem, each naming its key.
  std::string validate() const;
};

/// Every key above, by its member's name.
void readSimParams(wheelchair_core::ConfigReader& reader, SimParams& params);

/// The rear laser's parameters in the front laser's keys (laser_*), for a LaserSimulator.
SimParams rearLaserParams(const SimParams& params);

/// Reads and validates a YAML file of these keys; missing keys keep their defaults. Throws
/// wheelchair_core::ConfigError naming the file and the unknown, mistyped or invalid key.
SimParams loadSimParams(const std::string& yaml_path);

}  // namespace wheelchair_sim
