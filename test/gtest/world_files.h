// Reads a test world as the tests see it: the map (through the project's own map_server loader,
// wheelchair_core::loadMap, so the worlds and the loader check each other) and the world's
// named places and doorways.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_test {

enum class Cell : uint8_t { kFree, kOccupied, kUnknown };

/// A map as a grid of cells, row 0 at the bottom (y = origin_y), as in nav_msgs.
struct Grid {
  double resolution = 0.0;
  double origin_x = 0.0, origin_y = 0.0, origin_yaw = 0.0;
  std::string mode;  ///< the YAML's `mode`
  int width = 0, height = 0;
  std::vector<Cell> cells;
  std::vector<int> values;  ///< distinct nav_msgs cell values (-1, 0..100), sorted

  bool inBounds(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < width && iy < height; }
  Cell at(int ix, int iy) const { return cells[static_cast<size_t>(iy) * width + ix]; }
  bool free(int ix, int iy) const { return inBounds(ix, iy) && at(ix, iy) == Cell::kFree; }
  bool occupied(int ix, int iy) const { return inBounds(ix, iy) && at(ix, iy) == Cell::kOccupied; }
  int cellX(double x) const { return static_cast<int>(std::floor((x - origin_x) / resolution)); }
  int cellY(double y) const { return static_cast<int>(std::floor((y - origin_y) / resolution)); }
};

struct Place {
  std::string name, room;
  double x = 0, y = 0, yaw = 0;
};

struct Door {
  std::string name;
  double x = 0, y = 0, width = 0;
  char axis = 'x';  ///< the opening is measured along this axis
};

/// Throws std::runtime_error naming the file on any problem.
Grid loadWorldMap(const std::string& yaml_path);
std::vector<Place> loadPlaces(const std::string& places_yaml_path);
std::vector<Door> loadDoors(const std::string& doors_yaml_path);

}  // namespace wheelchair_test
