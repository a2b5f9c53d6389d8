// Does the chair's body touch the world? Its footprint, sampled, against the blocking cells of
// the ground-truth grid (wheelchair_core's polygon helpers place and fill the footprint).
#pragma once

#include <wheelchair_core/polygon.h>
#include <wheelchair_core/pose2d.h>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace wheelchair_sim {

class BodyContact {
 public:
  /// `footprint`: polygon in base_link [m] (ChairParams::footprint). Throws
  /// std::invalid_argument for fewer than 3 vertices or no world.
  BodyContact(const wheelchair_core::Polygon& footprint,
              std::shared_ptr<const mrpt::maps::COccupancyGridMap2D> world);

  /// True if any sample of the footprint's edges (every half cell) with base_link at `pose`
  /// lies on a blocking cell or outside the grid. Enough while the chair moves less than a
  /// cell per check: an obstacle can only enter through the outline.
  bool outlineTouches(const wheelchair_core::Pose2D& pose) const;

  /// outlineTouches, plus the interior every cell (after a teleport).
  bool touches(const wheelchair_core::Pose2D& pose) const;

 private:
  bool anyBlocked(const std::vector<Eigen::Vector2d>& samples,
                  const wheelchair_core::Pose2D& pose) const;

  double x_min_, y_min_, resolution_;
  int size_x_, size_y_;
  std::vector<uint8_t> blocked_;  ///< 1 per blocking cell, row-major (a copy: fast lookups)
  std::vector<Eigen::Vector2d> outline_, interior_;
};

}  // namespace wheelchair_sim
