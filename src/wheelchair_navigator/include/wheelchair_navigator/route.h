// The route being driven, as geometry: how far the chair still has to go along it, the stretch
// ahead that something blocks, whether another route goes through that stretch, and whether
// the obstacle layer has something on the route ahead.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace wheelchair_navigator {

using wheelchair_core::Pose2D;

class Route {
 public:
  Route() = default;
  explicit Route(std::vector<Pose2D> poses);

  bool empty() const { return poses_.empty(); }
  const std::vector<Pose2D>& poses() const { return poses_; }
  double length() const { return along_.empty() ? 0.0 : along_.back(); }

  /// Moves the cursor to the route vertex nearest to `pose` (searched forward from the cursor,
  /// so a route passing the same place twice is followed in order) and returns the distance
  /// still to go along the route [m].
  double advance(const Pose2D& pose);
  /// Distance along the route of the cursor [m].
  double cursorAlong() const { return along_.empty() ? 0.0 : along_[cursor_]; }

  /// The point `distance` [m] along the route from its start (clamped to its ends).
  Eigen::Vector2d pointAt(double distance) const;
  /// The polyline from `from` to `to` metres along the route (both ends interpolated).
  std::vector<Eigen::Vector2d> stretch(double from, double to) const;

 private:
  std::vector<Pose2D> poses_;
  std::vector<double> along_;  ///< distance of each vertex from the start
  size_t cursor_ = 0;
};

/// The smallest distance of the poses of `path` within `horizon` metres of its start to the
/// polyline `stretch` [m] (+inf for an empty path or stretch).
double distanceToStretch(const std::vector<Pose2D>& path,
                         const std::vector<Eigen::Vector2d>& stretch, double horizon);

/// The first cell of the obstacle layer on `route` ahead of its cursor (within `lookahead` m
/// along it and `corridor` m either side) that is occupied (>= 50) in `layer` and free in
/// `static_map` (an obstacle the map does not have); nullopt if none.
std::optional<Eigen::Vector2d> layerObstacleAhead(const Route& route,
                                                  const wheelchair_core::OccupancyMap& layer,
                                                  const wheelchair_core::OccupancyMap& static_map,
                                                  double lookahead, double corridor);

}  // namespace wheelchair_navigator
