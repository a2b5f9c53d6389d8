#include <wheelchair_description/chair_params.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace wheelchair_description {
namespace {

/// The number at root[key]; `name` is how the message calls it (e.g. "laser.x").
template <typename Key>
double requireNumber(const YAML::Node& root, const Key& key, const std::string& name,
                     const std::string& file) {
  const YAML::Node node = root[key];
  if (!node) throw std::runtime_error(file + ": missing parameter '" + name + "'");
  try {
    return node.as<double>();
  } catch (const YAML::Exception&) {
    throw std::runtime_error(file + ": parameter '" + name + "' is not a number");
  }
}

double requireNumber(const YAML::Node& root, const std::string& key, const std::string& file) {
  return requireNumber(root, key, key, file);
}

/// footprint: a sequence of [x, y] pairs.
std::vector<Eigen::Vector2d> requireFootprint(const YAML::Node& root, const std::string& file) {
  const YAML::Node node = root["footprint"];
  if (!node) throw std::runtime_error(file + ": missing parameter 'footprint'");
  if (!node.IsSequence())
    throw std::runtime_error(file + ": parameter 'footprint' is not a list of [x, y] points");
  std::vector<Eigen::Vector2d> footprint;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const YAML::Node vertex = node[i];
    const std::string name = "footprint[" + std::to_string(i) + "]";
    if (!vertex.IsSequence() || vertex.size() != 2)
      throw std::runtime_error(file + ": parameter '" + name + "' is not an [x, y] point");
    footprint.emplace_back(requireNumber(vertex, 0, name + "[0]", file),
                           requireNumber(vertex, 1, name + "[1]", file));
  }
  return footprint;
}

void requirePositive(double value, const char* name) {
  if (!std::isfinite(value) || value <= 0.0)
    throw std::invalid_argument(std::string("chair parameter '") + name +
                                "' must be finite and positive (got " + std::to_string(value) +
                                ")");
}

void requireFinite(double value, const char* name) {
  if (!std::isfinite(value))
    throw std::invalid_argument(std::string("chair parameter '") + name + "' is not finite");
}

}  // namespace

double ChairParams::circumscribedRadius() const {
  double radius = 0.0;
  for (const auto& vertex : footprint) radius = std::max(radius, vertex.norm());
  return radius;
}

void validate(const ChairParams& p) {
  const std::pair<double, const char*> positive[] = {{p.total_mass, "total_mass"},
                                                     {p.wheel_mass, "wheel_mass"},
                                                     {p.wheel_inertia, "wheel_inertia"},
                                                     {p.wheel_inertia_diam, "wheel_inertia_diam"},
                                                     {p.body_inertia, "body_inertia"},
                                                     {p.wheel_radius, "wheel_radius"},
                                                     {p.half_track, "half_track"},
                                                     {p.max_wheel_torque, "max_wheel_torque"},
                                                     {p.max_speed, "max_speed"},
                                                     {p.width, "width"},
                                                     {p.length, "length"}};
  for (const auto& [value, name] : positive) requirePositive(value, name);
  requireFinite(p.cm_offset, "cm_offset");
  if (!std::isfinite(p.lookahead) || p.lookahead == 0.0)
    throw std::invalid_argument("chair parameter 'lookahead' must be finite and non-zero (eq. 19)");
  if (!std::isfinite(p.rolling_resistance) || p.rolling_resistance < 0.0)
    throw std::invalid_argument("chair parameter 'rolling_resistance' must be >= 0");
  if (p.footprint.size() < 3)
    throw std::invalid_argument("chair parameter 'footprint' needs >= 3 vertices");
  for (const auto& v : p.footprint)
    if (!v.allFinite())
      throw std::invalid_argument("chair parameter 'footprint' has a non-finite vertex");
  requireFinite(p.laser_x, "laser.x");
  requireFinite(p.laser_y, "laser.y");
  requireFinite(p.laser_z, "laser.z");
  requireFinite(p.laser_yaw, "laser.yaw");
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
  p.footprint = requireFootprint(root, yaml_path);
  const YAML::Node laser = root["laser"];
  if (!laser || !laser.IsMap())
    throw std::runtime_error(yaml_path + ": missing parameter 'laser' {x, y, z, yaw}");
  p.laser_x = requireNumber(laser, "x", "laser.x", yaml_path);
  p.laser_y = requireNumber(laser, "y", "laser.y", yaml_path);
  p.laser_z = requireNumber(laser, "z", "laser.z", yaml_path);
  p.laser_yaw = requireNumber(laser, "yaw", "laser.yaw", yaml_path);
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
