#include <wheelchair_core/config.h>
#include <wheelchair_sim/sim_params.h>

#include <cmath>
#include <utility>

namespace wheelchair_sim {

std::string SimParams::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.check(std::isfinite(physics_rate) && physics_rate >= 500.0,
               "physics_rate must be >= 500 Hz (got " + std::to_string(physics_rate) + ")");
  checks.positive("resistance_smoothing", resistance_smoothing)
      .nonNegative("brake_torque", brake_torque)
      .nonNegative("slip_noise", slip_noise)
      .positive("laser_rate", laser_rate)
      .check(laser_beams >= 2, "laser_beams must be >= 2 (got " + std::to_string(laser_beams) + ")")
      .positive("laser_fov", laser_fov)
      .check(laser_fov <= 2.0 * M_PI, "laser_fov must be at most 2 pi")
      .nonNegative("laser_range_min", laser_range_min)
      .positive("laser_range_max", laser_range_max)
      .check(laser_range_max > laser_range_min, "laser_range_max must exceed laser_range_min")
      .nonNegative("laser_range_noise", laser_range_noise)
      .check(rear_laser_beams >= 2,
             "rear_laser_beams must be >= 2 (got " + std::to_string(rear_laser_beams) + ")")
      .positive("rear_laser_fov", rear_laser_fov)
      .check(rear_laser_fov <= 2.0 * M_PI, "rear_laser_fov must be at most 2 pi")
      .check(rear_laser_range_max > laser_range_min,
             "rear_laser_range_max must exceed laser_range_min")
      .positive("odom_rate", odom_rate)
      .nonNegative("odom_noise", odom_noise);
  const std::pair<double, const char*> relative_errors[] = {
      {odom_radius_error_right, "odom_radius_error_right"},
      {odom_radius_error_left, "odom_radius_error_left"},
      {odom_track_error, "odom_track_error"}};
  for (const auto& [error, name] : relative_errors)
    checks.check(std::isfinite(error) && std::abs(error) < 0.5,
                 std::string(name) + " must be in (-0.5, 0.5) (got " + std::to_string(error) + ")");
  return checks.result();
}

void readSimParams(wheelchair_core::ConfigReader& r, SimParams& p) {
  r.read("physics_rate", p.physics_rate);
  r.read("rolling_resistance", p.rolling_resistance);
  r.read("resistance_smoothing", p.resistance_smoothing);
  r.read("torque_limit", p.torque_limit);
  r.read("brake_torque", p.brake_torque);
  r.read("slip_noise", p.slip_noise);
  r.read("laser_enabled", p.laser_enabled);
  r.read("laser_rate", p.laser_rate);
  r.read("laser_beams", p.laser_beams);
  r.read("laser_fov", p.laser_fov);
  r.read("laser_range_min", p.laser_range_min);
  r.read("laser_range_max", p.laser_range_max);
  r.read("laser_range_noise", p.laser_range_noise);
  r.read("rear_laser_enabled", p.rear_laser_enabled);
  r.read("rear_laser_beams", p.rear_laser_beams);
  r.read("rear_laser_fov", p.rear_laser_fov);
  r.read("rear_laser_range_max", p.rear_laser_range_max);
  r.read("odom_rate", p.odom_rate);
  r.read("odom_radius_error_right", p.odom_radius_error_right);
  r.read("odom_radius_error_left", p.odom_radius_error_left);
  r.read("odom_track_error", p.odom_track_error);
  r.read("odom_noise", p.odom_noise);
  r.read("seed", p.seed);
}

SimParams rearLaserParams(const SimParams& params) {
  SimParams rear = params;
  rear.laser_enabled = params.rear_laser_enabled;
  rear.laser_beams = params.rear_laser_beams;
  rear.laser_fov = params.rear_laser_fov;
  rear.laser_range_max = params.rear_laser_range_max;
  rear.seed = params.seed + 101;  // its own noise
  return rear;
}

SimParams loadSimParams(const std::string& yaml_path) {
  return wheelchair_core::loadConfig<SimParams>(
      wheelchair_core::YamlParameterSource::fromFile(yaml_path), readSimParams);
}

}  // namespace wheelchair_sim
