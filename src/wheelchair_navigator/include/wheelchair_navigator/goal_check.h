// Is a destination one the chair can be at? Checked on the static map before any route is
// asked for, so that the rider hears "inside a wall or furniture" or "does not fit" rather
// than a planner's message. The chair's body at the goal pose is checked with the planner's own
// C-space and footprint checker (the same distance field, unknown cells as obstacles).
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_core/pose2d.h>
#include <wheelchair_navigator/reasons.h>

#include <memory>
#include <optional>
#include <string>

namespace wheelchair_planner {
class ConfigSpace;
class FootprintChecker;
}  // namespace wheelchair_planner

namespace wheelchair_navigator {

/// Why a goal cannot be driven to, with the numbers for the log.
struct GoalRefusal {
  Reason reason;       ///< kGoalOutsideMap, kGoalInObstacle or kGoalNoRoom
  std::string detail;  ///< e.g. "goal (6.05, 3.00): the body overlaps an obstacle by 0.28 m"
};

class GoalCheck {
 public:
  /// `footprint`: the chair's polygon in base_link; `inscribed_radius`: its half width (the
  /// planner's C-space disc). Throws std::invalid_argument on a map or polygon it cannot use.
  GoalCheck(const wheelchair_core::OccupancyMap& map, const wheelchair_core::Polygon& footprint,
            double inscribed_radius);
  ~GoalCheck();

  /// nullopt if the chair's body fits at `goal` with at least `min_clearance` [m]; else why not:
  /// outside the map, the point itself in an occupied or unknown cell, or the body overlapping.
  std::optional<GoalRefusal> check(const wheelchair_core::Pose2D& goal, double min_clearance) const;
  /// The static map's C-space it checks on (the chair's centre; see layer_cut.h).
  const wheelchair_planner::ConfigSpace& configSpace() const { return *cspace_; }

 private:
  std::unique_ptr<wheelchair_planner::ConfigSpace> cspace_;
  std::unique_ptr<wheelchair_planner::FootprintChecker> checker_;
};

}  // namespace wheelchair_navigator
