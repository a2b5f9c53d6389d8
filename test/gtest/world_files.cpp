#include "world_files.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <stdexcept>

namespace wheelchair_test {
namespace {

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

/// Next whitespace-separated header token of a PGM, skipping '#' comments.
std::string pgmToken(std::istream& in) {
  std::string token;
  char c;
  while (in.get(c)) {
    if (c == '#') {
      std::string comment;
      std::getline(in, comment);
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      if (!token.empty()) return token;
    } else {
      token += c;
    }
  }
  return token;
}

/// map_server's interpretation of a pixel in trinary mode with negate 0.
Cell classify(int value, double occupied_thresh, double free_thresh) {
  const double p = (255.0 - value) / 255.0;
  if (p > occupied_thresh) return Cell::kOccupied;
  if (p < free_thresh) return Cell::kFree;
  return Cell::kUnknown;
}

}  // namespace

Grid loadWorldMap(const std::string& yaml_path) {
  const YAML::Node doc = YAML::LoadFile(yaml_path);
  Grid grid;
  grid.resolution = doc["resolution"].as<double>();
  const auto origin = doc["origin"].as<std::vector<double>>();
  if (origin.size() != 3) throw std::runtime_error(yaml_path + ": origin must have 3 numbers");
  grid.origin_x = origin[0];
  grid.origin_y = origin[1];
  grid.origin_yaw = origin[2];
  grid.mode = doc["mode"] ? doc["mode"].as<std::string>() : "trinary";
  const double occupied_thresh = doc["occupied_thresh"].as<double>();
  const double free_thresh = doc["free_thresh"].as<double>();
  if (doc["negate"].as<int>() != 0) throw std::runtime_error(yaml_path + ": negate must be 0");

  const std::string image_path = directoryOf(yaml_path) + "/" + doc["image"].as<std::string>();
  std::ifstream in(image_path, std::ios::binary);
  if (!in) throw std::runtime_error(image_path + ": cannot open");
  if (pgmToken(in) != "P5") throw std::runtime_error(image_path + ": not a binary PGM (P5)");
  grid.width = std::stoi(pgmToken(in));
  grid.height = std::stoi(pgmToken(in));
  if (std::stoi(pgmToken(in)) != 255) throw std::runtime_error(image_path + ": maxval not 255");
  std::vector<unsigned char> pixels(static_cast<size_t>(grid.width) * grid.height);
  in.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
  if (in.gcount() != static_cast<std::streamsize>(pixels.size())) {
    throw std::runtime_error(image_path + ": truncated");
  }
  grid.cells.resize(pixels.size());
  std::set<int> values;
  for (int row = 0; row < grid.height; ++row) {  // image row 0 is the top of the map
    for (int ix = 0; ix < grid.width; ++ix) {
      const int value = pixels[static_cast<size_t>(row) * grid.width + ix];
      values.insert(value);
      const int iy = grid.height - 1 - row;
      grid.cells[static_cast<size_t>(iy) * grid.width + ix] =
          classify(value, occupied_thresh, free_thresh);
    }
  }
  grid.pixel_values.assign(values.begin(), values.end());
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
