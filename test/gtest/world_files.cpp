#include "world_files.h"

#include <wheelchair_core/map_io.h>
#include <yaml-cpp/yaml.h>

#include <set>
#include <stdexcept>

namespace wheelchair_test {

Grid loadWorldMap(const std::string& yaml_path) {
  const wheelchair_core::OccupancyMap map = wheelchair_core::loadMap(yaml_path);
  Grid grid;
  grid.resolution = map.resolution;
  grid.origin_x = map.origin_x;
  grid.origin_y = map.origin_y;
  grid.origin_yaw = map.origin_yaw;
  const YAML::Node doc = YAML::LoadFile(yaml_path);
  grid.mode = doc["mode"] ? doc["mode"].as<std::string>() : "trinary";
  grid.width = map.width;
  grid.height = map.height;
  std::set<int> values;
  grid.cells.reserve(map.data.size());
  for (const int8_t value : map.data) {
    values.insert(value);
    grid.cells.push_back(value == wheelchair_core::kFree       ? Cell::kFree
                         : value == wheelchair_core::kOccupied ? Cell::kOccupied
                                                               : Cell::kUnknown);
  }
  grid.values.assign(values.begin(), values.end());
  return grid;
}

std::vector<Place> loadPlaces(const std::string& places_yaml_path) {
  std::vector<Place> places;
  for (const auto& node : YAML::LoadFile(places_yaml_path)["places"]) {
    places.push_back({node["name"].as<std::string>(), node["room"].as<std::string>(),
                      node["x"].as<double>(), node["y"].as<double>(), node["yaw"].as<double>()});
  }
  return places;
}

std::vector<Door> loadDoors(const std::string& doors_yaml_path) {
  std::vector<Door> doors;
  for (const auto& node : YAML::LoadFile(doors_yaml_path)["doors"]) {
    const auto axis = node["axis"].as<std::string>();
    if (axis != "x" && axis != "y") throw std::runtime_error(doors_yaml_path + ": bad axis");
    doors.push_back({node["name"].as<std::string>(), node["x"].as<double>(), node["y"].as<double>(),
                     node["width"].as<double>(), axis[0]});
  }
  return doors;
}

}  // namespace wheelchair_test
