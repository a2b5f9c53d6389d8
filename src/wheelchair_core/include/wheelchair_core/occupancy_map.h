// A ROS-free occupancy grid in the nav_msgs/OccupancyGrid convention, the common currency
// between map files, the map server, the simulator, the localizer and the planners.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace wheelchair_core {

/// Cell values as in nav_msgs/OccupancyGrid: -1 unknown, 0 free ... 100 occupied.
constexpr int8_t kUnknown = -1;
constexpr int8_t kFree = 0;
constexpr int8_t kOccupied = 100;

struct OccupancyMap {
  double resolution = 0.05;  ///< [m / cell]
  double origin_x = 0.0;     ///< world pose of the lower-left corner of cell (0, 0) [m]
  double origin_y = 0.0;
  double origin_yaw = 0.0;  ///< [rad]; only 0 is supported by the consumers
  int width = 0;            ///< cells along x
  int height = 0;           ///< cells along y
  /// Row-major, row 0 at the bottom (y = origin_y), as in nav_msgs/OccupancyGrid.
  std::vector<int8_t> data;

  bool inBounds(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < width && iy < height; }
  int8_t at(int ix, int iy) const { return data[static_cast<size_t>(iy) * width + ix]; }
  int8_t& at(int ix, int iy) { return data[static_cast<size_t>(iy) * width + ix]; }
  /// Cell containing world point (x, y); false if outside the map.
  bool worldToCell(double x, double y, int& ix, int& iy) const;
  /// World coordinates of the centre of cell (ix, iy).
  void cellToWorld(int ix, int iy, double& x, double& y) const;
};

}  // namespace wheelchair_core
