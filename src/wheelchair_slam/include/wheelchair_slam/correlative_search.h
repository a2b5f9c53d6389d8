// Brute-force correlative scan matching (Olson 2009): the scan's points scored on a likelihood
// grid of a reference point set (each cell: exp(-d^2 / 2 sigma^2), d = distance to the nearest
// reference point) over a window of poses. Finds a loop closure's relative pose far from the
// guess, where ICP alone would fall into a wrong local minimum.
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_slam/scan_points.h>

#include <vector>

namespace wheelchair_slam {

class LikelihoodGrid {
 public:
  /// Grid over the bounding box of `points` plus a margin, cells of `resolution`, likelihood
  /// with standard deviation `sigma` (cut off at 3 sigma).
  LikelihoodGrid(const Points& points, double resolution, double sigma);
  /// Likelihood at a point (0 outside the grid).
  double at(const Eigen::Vector2d& p) const;
  /// Mean likelihood of `points` (sensor frame) at `pose`, 0..1.
  double score(const Points& points, const wheelchair_core::Pose2D& pose) const;
  double resolution() const { return resolution_; }
  const Eigen::Vector2d& origin() const { return origin_; }  ///< corner of cell (0, 0)
  int width() const { return width_; }
  int height() const { return height_; }
  const float* row(int y) const { return cells_.data() + static_cast<size_t>(y) * width_; }

 private:
  double resolution_;
  Eigen::Vector2d origin_;
  int width_ = 0, height_ = 0;
  std::vector<float> cells_;
};

struct SearchWindow {
  double xy = 1.0;    ///< half width in x and y [m]
  double yaw = 0.25;  ///< half width [rad]
  double step_yaw = 0.015;
};

struct SearchResult {
  wheelchair_core::Pose2D pose;
  double score = 0.0;         ///< mean likelihood of the best pose
  double second_score = 0.0;  ///< best score farther than 3 cells / 3 steps from the best
};

/// The best pose of `points` within `window` around `guess`, translations on the grid's cells.
SearchResult correlativeSearch(const LikelihoodGrid& grid, const Points& points,
                               const wheelchair_core::Pose2D& guess, const SearchWindow& window);

}  // namespace wheelchair_slam
