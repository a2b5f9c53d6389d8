#include <wheelchair_core/config.h>
#include <wheelchair_description/chair_params.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace wheelchair_description {
namespace {

using wheelchair_core::ConfigError;

std::string number(double value) {
  std::ostringstream os;
  os << std::setprecision(6) << value;
  return os.str();
}

std::string named(const char* name) { return std::string("chair parameter '") + name + "'"; }

/// Throws ConfigError unless the source holds some key of the group `name` ("laser/x"...).
void requireGroup(const wheelchair_core::ConfigReader& reader, const std::string& name,
                  const std::string& members) {
  for (const std::string& key : reader.source().keys())
    if (key.compare(0, name.size() + 1, name + "/") == 0) return;
  throw ConfigError(reader.source().where() + ": missing parameter '" + name + "' " + members);
}

}  // namespace

std::string ChairParams::validate() const {
  wheelchair_core::ConfigChecks checks;
  const std::pair<double, const char*> positive[] = {{total_mass, "total_mass"},
                                                     {wheel_mass, "wheel_mass"},
                                                     {wheel_inertia, "wheel_inertia"},
                                                     {wheel_inertia_diam, "wheel_inertia_diam"},
                                                     {body_inertia, "body_inertia"},
                                                     {wheel_radius, "wheel_radius"},
                                                     {half_track, "half_track"},
                                                     {max_wheel_torque, "max_wheel_torque"},
                                                     {max_speed, "max_speed"},
                                                     {width, "width"},
                                                     {length, "length"}};
  for (const auto& [value, name] : positive)
    checks.check(std::isfinite(value) && value > 0.0,
                 named(name) + " must be finite and positive (got " + number(value) + ")");
  checks.check(std::isfinite(cm_offset), named("cm_offset") + " is not finite");
  checks.check(std::isfinite(lookahead) && lookahead != 0.0,
               named("lookahead") + " must be finite and non-zero (eq. 19)");
  checks.check(std::isfinite(rolling_resistance) && rolling_resistance >= 0.0,
               named("rolling_resistance") + " must be >= 0");
  const std::string polygon = wheelchair_core::polygonProblem(footprint);
  checks.check(polygon.empty(), named("footprint") + ": " + polygon);
  const std::pair<double, const char*> mount[] = {
      {laser_x, "laser/x"},           {laser_y, "laser/y"},
      {laser_z, "laser/z"},           {laser_yaw, "laser/yaw"},
      {rear_laser_x, "rear_laser/x"}, {rear_laser_y, "rear_laser/y"},
      {rear_laser_z, "rear_laser/z"}, {rear_laser_yaw, "rear_laser/yaw"}};
  for (const auto& [value, name] : mount)
    checks.check(std::isfinite(value), named(name) + " is not finite");
  const std::pair<double, const char*> stop_positive[] = {
      {stop.brake_decel, "protective_field/brake_decel"},
      {stop.brake_jerk, "protective_field/brake_jerk"}};
  for (const auto& [value, name] : stop_positive)
    checks.check(std::isfinite(value) && value > 0.0,
                 named(name) + " must be finite and positive (got " + number(value) + ")");
  const std::pair<double, const char*> stop_non_negative[] = {
      {stop.reaction_time, "protective_field/reaction_time"},
      {stop.drive_accel, "protective_field/drive_accel"},
      {stop.margin, "protective_field/margin"}};
  for (const auto& [value, name] : stop_non_negative)
    checks.check(std::isfinite(value) && value >= 0.0,
                 named(name) + " must be finite and >= 0 (got " + number(value) + ")");
  return checks.result();
}

void readChairParams(wheelchair_core::ConfigReader& reader, ChairParams& p) {
  reader.require("total_mass", p.total_mass);
  reader.require("wheel_mass", p.wheel_mass);
  reader.require("wheel_inertia", p.wheel_inertia);
  reader.require("wheel_inertia_diam", p.wheel_inertia_diam);
  reader.require("body_inertia", p.body_inertia);
  reader.require("wheel_radius", p.wheel_radius);
  reader.require("half_track", p.half_track);
  reader.require("cm_offset", p.cm_offset);
  reader.require("lookahead", p.lookahead);
  reader.require("max_wheel_torque", p.max_wheel_torque);
  reader.require("max_speed", p.max_speed);
  reader.require("rolling_resistance", p.rolling_resistance);
  reader.require("width", p.width);
  reader.require("length", p.length);
  reader.require("footprint", p.footprint);
  requireGroup(reader, "laser", "{x, y, z, yaw}");
  reader.require("laser/x", p.laser_x);
  reader.require("laser/y", p.laser_y);
  reader.require("laser/z", p.laser_z);
  reader.require("laser/yaw", p.laser_yaw);
  requireGroup(reader, "rear_laser", "{x, y, z, yaw}");
  reader.require("rear_laser/x", p.rear_laser_x);
  reader.require("rear_laser/y", p.rear_laser_y);
  reader.require("rear_laser/z", p.rear_laser_z);
  reader.require("rear_laser/yaw", p.rear_laser_yaw);
  requireGroup(reader, "protective_field",
               "{reaction_time, brake_decel, brake_jerk, drive_accel, margin}");
  reader.require("protective_field/reaction_time", p.stop.reaction_time);
  reader.require("protective_field/brake_decel", p.stop.brake_decel);
  reader.require("protective_field/brake_jerk", p.stop.brake_jerk);
  reader.require("protective_field/drive_accel", p.stop.drive_accel);
  reader.require("protective_field/margin", p.stop.margin);
}

ChairParams loadChairParams(const std::string& yaml_path) {
  if (!std::ifstream(yaml_path)) throw ConfigError(yaml_path + ": cannot open chair file");
  YAML::Node root;
  try {
    root = YAML::LoadFile(yaml_path);
  } catch (const YAML::Exception& e) {
    throw ConfigError(yaml_path + ": bad YAML: " + e.what());
  }
  return wheelchair_core::loadConfig<ChairParams>(
      wheelchair_core::YamlParameterSource(root, yaml_path), readChairParams);
}

}  // namespace wheelchair_description
