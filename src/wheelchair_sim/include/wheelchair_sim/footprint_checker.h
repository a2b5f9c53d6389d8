// Does the chair's footprint overlap an obstacle of the ground-truth grid?
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>

#include <cstdint>

#include <memory>
#include <vector>

namespace wheelchair_sim {

/// A cell blocks the chair (and reflects the laser) when its probability of being free is
/// below this: occupied cells do, unknown (0.5) and free cells do not.
constexpr float kFreeThreshold = 0.45f;

class FootprintChecker {
 public:
  /// `footprint`: polygon in base_link [m], counter-clockwise (ChairParams::footprint).
  FootprintChecker(std::vector<Eigen::Vector2d> footprint,
                   std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world);

  /// True if any sample of the footprint's edges (every half cell) at base_link pose
  /// (x, y, theta) lies on a blocking cell or outside the grid. Enough while the chair moves
  /// less than a cell per check: an obstacle can only enter through the outline.
  bool outlineCollides(const Eigen::Vector3d& pose) const;

  /// outlineCollides, plus the interior every cell (after a teleport).
  bool collides(const Eigen::Vector3d& pose) const;

 private:
  bool anyBlocked(const std::vector<Eigen::Vector2d>& samples, const Eigen::Vector3d& pose) const;

  double x_min_, y_min_, resolution_;
  int size_x_, size_y_;
  std::vector<uint8_t> blocked_;  ///< 1 per blocking cell, row-major (a copy: fast lookups)
  std::vector<Eigen::Vector2d> outline_, interior_;
};

/// True if point p lies inside polygon `poly` (even-odd rule).
bool insidePolygon(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p);

}  // namespace wheelchair_sim
