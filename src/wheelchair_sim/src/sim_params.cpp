#include <wheelchair_sim/sim_params.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <set>
#include <stdexcept>

namespace wheelchair_sim {
namespace {

void require(bool ok, const std::string& name, double value, const char* rule) {
  if (!ok) {
    throw std::invalid_argument("sim parameter " + name + " " + rule + " (got " +
                                std::to_string(value) + ")");
  }
}

}  // namespace

SimParams loadSimParams(const std::string& yaml_path) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(yaml_path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(yaml_path + ": " + e.what());
  }
  SimParams p;
  std::set<std::string> known;
  forEachParam(p, [&](const char* name, auto& value) {
    known.insert(name);
    if (!root[name]) return;
    try {
      value = root[name].template as<std::remove_reference_t<decltype(value)>>();
    } catch (const YAML::Exception&) {
      throw std::runtime_error(yaml_path + ": key " + name + " has the wrong type");
    }
  });
  for (const auto& kv : root) {
    const std::string key = kv.first.as<std::string>();
    if (!known.count(key)) throw std::runtime_error(yaml_path + ": unknown key " + key);
  }
  try {
    validate(p);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(yaml_path + ": " + e.what());
  }
  return p;
}

void validate(const SimParams& p) {
  auto finite_nonneg = [](double v) { return std::isfinite(v) && v >= 0.0; };
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  require(std::isfinite(p.physics_rate) && p.physics_rate >= 500.0, "physics_rate", p.physics_rate,
          "must be >= 500 Hz");
  require(positive(p.resistance_smoothing), "resistance_smoothing", p.resistance_smoothing,
          "must be positive");
  require(finite_nonneg(p.brake_torque), "brake_torque", p.brake_torque, "must be >= 0");
  require(finite_nonneg(p.slip_noise), "slip_noise", p.slip_noise, "must be >= 0");
  require(positive(p.laser_rate), "laser_rate", p.laser_rate, "must be positive");
  require(p.laser_beams >= 2, "laser_beams", p.laser_beams, "must be >= 2");
  require(positive(p.laser_fov) && p.laser_fov <= 2.0 * M_PI, "laser_fov", p.laser_fov,
          "must be in (0, 2 pi]");
  require(finite_nonneg(p.laser_range_min), "laser_range_min", p.laser_range_min, "must be >= 0");
  require(positive(p.laser_range_max) && p.laser_range_max > p.laser_range_min, "laser_range_max",
          p.laser_range_max, "must exceed laser_range_min");
  require(finite_nonneg(p.laser_range_noise), "laser_range_noise", p.laser_range_noise,
          "must be >= 0");
  require(positive(p.odom_rate), "odom_rate", p.odom_rate, "must be positive");
  for (double e : {p.odom_radius_error_right, p.odom_radius_error_left, p.odom_track_error}) {
    require(std::isfinite(e) && std::abs(e) < 0.5, "odom_*_error", e, "must be in (-0.5, 0.5)");
  }
  require(finite_nonneg(p.odom_noise), "odom_noise", p.odom_noise, "must be >= 0");
}

std::string defaultSimParamsPath() {
  const std::string source = std::string(WHEELCHAIR_SIM_SOURCE_DIR) + "/config/sim.yaml";
  if (std::ifstream(source).good()) return source;
  return std::string(WHEELCHAIR_SIM_INSTALL_DIR) + "/config/sim.yaml";
}

}  // namespace wheelchair_sim
