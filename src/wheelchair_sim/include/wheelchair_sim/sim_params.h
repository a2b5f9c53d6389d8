// The simulator's own parameters (what the chair's YAML does not say: integration rate,
// disturbances, sensor models). One flat YAML, config/sim.yaml; every key can be
// overridden by a ROS private parameter of the same name in the nodelet.
#pragma once

#include <cstdint>
#include <string>

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
  // Wheel-encoder odometry errors.
  double odom_rate = 50.0;               ///< [Hz] of /odom and tf odom -> base_link
  double odom_radius_error_right = 0.0;  ///< relative error of the assumed right radius
  double odom_radius_error_left = 0.0;   ///< relative error of the assumed left radius
  double odom_track_error = 0.0;         ///< relative error of the assumed half track b
  double odom_noise = 0.0;               ///< random wheel-travel error [m per sqrt(m)]
  int seed = 1;                          ///< seed of every random generator of the run
};

/// Calls visit(name, value&) for every field, so the YAML loader and the ROS parameter
/// reader share one list of names.
template <typename Visitor>
void forEachParam(SimParams& p, Visitor&& visit) {
  visit("physics_rate", p.physics_rate);
  visit("rolling_resistance", p.rolling_resistance);
  visit("resistance_smoothing", p.resistance_smoothing);
  visit("torque_limit", p.torque_limit);
  visit("brake_torque", p.brake_torque);
  visit("slip_noise", p.slip_noise);
  visit("laser_enabled", p.laser_enabled);
  visit("laser_rate", p.laser_rate);
  visit("laser_beams", p.laser_beams);
  visit("laser_fov", p.laser_fov);
  visit("laser_range_min", p.laser_range_min);
  visit("laser_range_max", p.laser_range_max);
  visit("laser_range_noise", p.laser_range_noise);
  visit("odom_rate", p.odom_rate);
  visit("odom_radius_error_right", p.odom_radius_error_right);
  visit("odom_radius_error_left", p.odom_radius_error_left);
  visit("odom_track_error", p.odom_track_error);
  visit("odom_noise", p.odom_noise);
  visit("seed", p.seed);
}

/// Reads a flat YAML file; missing keys keep their defaults, unknown keys are an error.
/// Throws std::runtime_error naming the file and the key. The result is validated.
SimParams loadSimParams(const std::string& yaml_path);

/// Throws std::invalid_argument naming the first bad value.
void validate(const SimParams& params);

/// config/sim.yaml of this package (source tree, else install space).
std::string defaultSimParamsPath();

}  // namespace wheelchair_sim
