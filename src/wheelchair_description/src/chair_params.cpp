#include <wheelchair_description/chair_params.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <stdexcept>

namespace wheelchair_description {
namespace {

double requireNumber(const YAML::Node& root, const std::string& key, const std::string& file) {
  const YAML::Node node = root[key];
  if (!node) throw std::runtime_error(file + ": missing parameter '" + key + "'");
  try {
    return node.as<double>();
  } catch (const YAML::Exception&) {
    throw std::runtime_error(file + ": parameter '" + key + "' is not a number");
  }
}

void requirePositive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0)
    throw std::invalid_argument(std::string("chair parameter '") + name +
                                "' must be finite and positive (got " + std::to_string(value) +
                                ")");
}

}  // namespace

double ChairParams::circumscribedRadius() const {
  double radius = 0.0;
  for (const auto& vertex : footprint) radius = std::max(radius, vertex.norm());
  return radius;
}

void validate(const ChairParams& p) {
  requirePositive(p.total_mass, "total_mass");
  requirePositive(p.wheel_mass, "wheel_mass");
  requirePositive(p.wheel_inertia, "wheel_inertia");
  requirePositive(p.wheel_inertia_diam, "wheel_inertia_diam");
  requirePositive(p.body_inertia, "body_inertia");
  requirePositive(p.wheel_radius, "wheel_radius");
  requirePositive(p.half_track, "half_track");
  requirePositive(p.max_wheel_torque, "max_wheel_torque");
  requirePositive(p.max_speed, "max_speed");
  requirePositive(p.width, "width");
  requirePositive(p.length, "length");
  if (!std::isfinite(p.cm_offset))
    throw std::invalid_argument("chair parameter 'cm_offset' is not finite");
  if (!std::isfinite(p.lookahead) || p.lookahead == 0.0)
    throw std::invalid_argument("chair parameter 'lookahead' must be finite and non-zero (eq. 19)");
  if (!std::isfinite(p.rolling_resistance) || p.rolling_resistance < 0.0)
    throw std::invalid_argument("chair parameter 'rolling_resistance' must be >= 0");
  if (p.footprint.size() < 3) throw std::invalid_argument("chair footprint needs >= 3 vertices");
  for (const auto& v : p.footprint)
    if (!v.allFinite()) throw std::invalid_argument("chair footprint has a non-finite vertex");
  if (!std::isfinite(p.laser_x) || !std::isfinite(p.laser_y) || !std::isfinite(p.laser_z) ||
      !std::isfinite(p.laser_yaw))
    throw std::invalid_argument("chair laser mount is not finite");
}

ChairParams loadChairParams(const std::string& yaml_path) {
  if (!std::ifstream(yaml_path)) throw std::runtime_error(yaml_path + ": cannot open chair file");
  YAML::Node root;
  try {
    root = YAML::LoadFile(yaml_path);
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(yaml_path + ": bad YAML: " + e.what());
  }
  ChairParams p;
  p.total_mass = requireNumber(root, "total_mass", yaml_path);
  p.wheel_mass = requireNumber(root, "wheel_mass", yaml_path);
  p.wheel_inertia = requireNumber(root, "wheel_inertia", yaml_path);
  p.wheel_inertia_diam = requireNumber(root, "wheel_inertia_diam", yaml_path);
  p.body_inertia = requireNumber(root, "body_inertia", yaml_path);
  p.wheel_radius = requireNumber(root, "wheel_radius", yaml_path);
  p.half_track = requireNumber(root, "half_track", yaml_path);
  p.cm_offset = requireNumber(root, "cm_offset", yaml_path);
  p.lookahead = requireNumber(root, "lookahead", yaml_path);
  p.max_wheel_torque = requireNumber(root, "max_wheel_torque", yaml_path);
  p.max_speed = requireNumber(root, "max_speed", yaml_path);
  p.rolling_resistance = requireNumber(root, "rolling_resistance", yaml_path);
  p.width = requireNumber(root, "width", yaml_path);
  p.length = requireNumber(root, "length", yaml_path);
  try {
    for (const auto& vertex : root["footprint"])
      p.footprint.emplace_back(vertex[0].as<double>(), vertex[1].as<double>());
    const YAML::Node laser = root["laser"];
    if (!laser) throw std::runtime_error(yaml_path + ": missing parameter 'laser'");
    p.laser_x = laser["x"].as<double>();
    p.laser_y = laser["y"].as<double>();
    p.laser_z = laser["z"].as<double>();
    p.laser_yaw = laser["yaw"].as<double>();
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(yaml_path + ": bad footprint or laser mount: " + e.what());
  }
  try {
    validate(p);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(yaml_path + ": " + e.what());
  }
  return p;
}

std::string defaultChairParamsPath() {
  for (const char* dir : {WHEELCHAIR_DESCRIPTION_INSTALL_DIR, WHEELCHAIR_DESCRIPTION_SOURCE_DIR}) {
    const std::string path = std::string(dir) + "/config/chair.yaml";
    if (std::ifstream(path)) return path;
  }
  return std::string(WHEELCHAIR_DESCRIPTION_SOURCE_DIR) + "/config/chair.yaml";
}

}  // namespace wheelchair_description
