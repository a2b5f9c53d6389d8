// Does the chair's footprint overlap an obstacle of the ground-truth grid?
#pragma once

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>

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

  /// True if any sample of the footprint (edges every half cell, interior every cell) at
  /// base_link pose (x, y, theta) lies on a blocking cell or outside the grid.
  bool collides(const Eigen::Vector3d& pose) const;

  /// The base_link sample points (for tests and visualization).
  const std::vector<Eigen::Vector2d>& samples() const { return samples_; }

 private:
  bool blocked(double x, double y) const;

  std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world_;
  std::vector<Eigen::Vector2d> samples_;
};

/// True if point p lies inside polygon `poly` (even-odd rule).
bool insidePolygon(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p);

}  // namespace wheelchair_sim
