// The shortest Reeds-Shepp path between two poses (OMPL's ReedsSheppStateSpace), sampled as plan
// poses: the footprint search's analytic expansion (as in Nav2's Smac Hybrid-A*), which reaches
// the goal pose exactly, backing into it where that is shorter. Internal header of
// search_attempt.cpp.
#pragma once

#include <wheelchair_core/pose2d.h>

#include <vector>

namespace wheelchair_planner {

using wheelchair_core::Pose2D;

struct ReedsSheppShot {
  std::vector<Pose2D> poses;   ///< from the start pose to the goal pose (both included)
  double length = 0.0;         ///< [m]
  double reversed = 0.0;       ///< [m] driven in reverse
  int cusps = 0;               ///< changes of direction within the path
  bool first_reverse = false;  ///< the first segment is driven in reverse
  double shortest_run = 0.0;   ///< [m] the shortest stretch driven one way
};

/// The shortest Reeds-Shepp path from `from` to `to` with turning radius `radius` [m], its
/// poses at most `step` apart (segment ends included), yaw = the chair's heading.
ReedsSheppShot reedsSheppShot(const Pose2D& from, const Pose2D& to, double radius, double step);

}  // namespace wheelchair_planner
