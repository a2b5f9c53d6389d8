#include <wheelchair_hmi/places.h>

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <set>
#include <stdexcept>

namespace wheelchair_hmi {
namespace {

double finiteNumber(const YAML::Node& entry, const char* key, const std::string& where) {
  if (!entry[key]) throw std::runtime_error(where + ": missing '" + key + "'");
  const double value = entry[key].as<double>();
  if (!std::isfinite(value)) throw std::runtime_error(where + ": '" + key + "' is not finite");
  return value;
}

}  // namespace

std::vector<Place> loadPlaces(const std::string& yaml_path) {
  if (!std::ifstream(yaml_path)) throw std::runtime_error(yaml_path + ": cannot open places file");
  std::vector<Place> places;
  std::set<std::string> names;
  try {
    const YAML::Node root = YAML::LoadFile(yaml_path);
    const YAML::Node list = root["places"];
    if (!list || !list.IsSequence() || list.size() == 0)
      throw std::runtime_error(yaml_path + ": no 'places' list");
    for (size_t i = 0; i < list.size(); ++i) {
      const YAML::Node entry = list[i];
      const std::string where = yaml_path + ": place " + std::to_string(i + 1);
      if (!entry["name"]) throw std::runtime_error(where + ": missing 'name'");
      Place place;
      place.name = entry["name"].as<std::string>();
      place.room = entry["room"] ? entry["room"].as<std::string>() : std::string("places");
      place.pose.x = finiteNumber(entry, "x", where);
      place.pose.y = finiteNumber(entry, "y", where);
      place.pose.yaw = entry["yaw"] ? finiteNumber(entry, "yaw", where) : 0.0;
      if (!names.insert(place.name).second)
        throw std::runtime_error(where + ": duplicate name '" + place.name + "'");
      places.push_back(place);
    }
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(yaml_path + ": bad YAML: " + e.what());
  }
  return places;
}

const Place* findPlace(const std::vector<Place>& places, const std::string& name) {
  for (const auto& place : places)
    if (place.name == name) return &place;
  return nullptr;
}

}  // namespace wheelchair_hmi
