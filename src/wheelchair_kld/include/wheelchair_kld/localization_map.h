// The map as the localizer needs it: MRPT's occupancy grid plus what is precomputed once from
// it (distance to the nearest obstacle for the likelihood field, the list of free cells for
// uniform sampling, an obstacle mask for ray casting).
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/random/RandomGenerators.h>

#include <cstdint>
#include <vector>

namespace wheelchair_kld {

class LocalizationMap {
 public:
  /// `max_distance` caps the obstacle distance transform [m].
  LocalizationMap(const mrpt::maps::COccupancyGridMap2D& grid, double max_distance);

  const mrpt::maps::COccupancyGridMap2D& grid() const { return grid_; }
  int sizeX() const { return size_x_; }
  int sizeY() const { return size_y_; }
  double resolution() const { return resolution_; }
  /// Cell index of a world point, or -1 outside the map.
  int cellIndex(double x, double y) const {
    const int ix = static_cast<int>(std::floor((x - x_min_) * inv_resolution_));
    const int iy = static_cast<int>(std::floor((y - y_min_) * inv_resolution_));
    if (ix < 0 || iy < 0 || ix >= size_x_ || iy >= size_y_) return -1;
    return iy * size_x_ + ix;
  }
  /// Distance from cell centre to the nearest obstacle surface cell (an obstacle cell with a
  /// non-obstacle 4-neighbour) [m], capped at max_distance: outside obstacles this is the
  /// distance to the nearest obstacle, inside a thick wall the depth below its surface.
  const std::vector<float>& obstacleDistance() const { return distance_; }
  bool isObstacle(int cell) const { return cell >= 0 && distance_[cell] == 0.0f; }
  bool isFree(int cell) const { return cell >= 0 && free_mask_[cell]; }
  double maxDistance() const { return max_distance_; }
  size_t freeCellCount() const { return free_cells_.size(); }
  /// A pose uniformly distributed over the known-free space (any heading).
  mrpt::math::TPose2D sampleFreePose(mrpt::random::CRandomGenerator& rng) const;
  /// Length of the ray from (x, y) along `angle` to the first obstacle, or max_range.
  double castRay(double x, double y, double angle, double max_range) const;

 private:
  mrpt::maps::COccupancyGridMap2D grid_;
  int size_x_, size_y_;
  double x_min_, y_min_, resolution_, inv_resolution_, max_distance_;
  std::vector<float> distance_;
  std::vector<uint8_t> free_mask_;
  std::vector<int> free_cells_;
};

}  // namespace wheelchair_kld
