#include <wheelchair_core/occupancy_map.h>

#include <cmath>

namespace wheelchair_core {

bool OccupancyMap::worldToCell(double x, double y, int& ix, int& iy) const {
  const double fx = std::floor((x - origin_x) / resolution);
  const double fy = std::floor((y - origin_y) / resolution);
  if (!std::isfinite(fx) || !std::isfinite(fy) || fx < 0 || fy < 0 || fx >= width || fy >= height) {
    return false;
  }
  ix = static_cast<int>(fx);
  iy = static_cast<int>(fy);
  return true;
}

void OccupancyMap::cellToWorld(int ix, int iy, double& x, double& y) const {
  x = origin_x + (ix + 0.5) * resolution;
  y = origin_y + (iy + 0.5) * resolution;
}

}  // namespace wheelchair_core
