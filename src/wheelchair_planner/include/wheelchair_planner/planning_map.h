// A map as every plugin plans on it: the chair's C-space and the footprint checker on it, and
// the end of every plugin's makePlan (the first stage's path through the footprint gate).
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_planner/certificate.h>
#include <wheelchair_planner/config_space.h>
#include <wheelchair_planner/footprint_checker.h>
#include <wheelchair_planner/planner_settings.h>

#include <string>
#include <vector>

namespace wheelchair_planner {

class PlanningMap {
 public:
  /// Throws std::invalid_argument on a map or settings it cannot use.
  PlanningMap(const wheelchair_core::OccupancyMap& map, const PlannerSettings& settings);
  PlanningMap(const PlanningMap&) = delete;
  PlanningMap& operator=(const PlanningMap&) = delete;

  const ConfigSpace& cspace() const { return cspace_; }
  /// The same for `map`, a map of this grid with some cells changed, in place (ConfigSpace::
  /// update; the checker stays on it).
  ConfigSpaceChange update(const wheelchair_core::OccupancyMap& map) { return cspace_.update(map); }
  const FootprintChecker& checker() const { return checker_; }

  /// The end of a plugin's makePlan: `plan` (the first stage's path from the start position to
  /// the goal, headings assigned) must stay in the free C-space (else `leaves_cspace` is the
  /// failure reason), then pass the footprint gate, which may replace it; the certificate gets
  /// `stage` and the path figures. Returns whether the plan may be driven.
  bool gateFirstStagePath(const FootprintGateParams& gate, const std::string& stage,
                          const std::string& leaves_cspace, const Pose2D& start, const Pose2D& goal,
                          std::vector<Pose2D>& plan, Certificate& cert) const;

 private:
  ConfigSpace cspace_;
  FootprintChecker checker_;  ///< on cspace_
};

/// `map` with every cell that `obstacles` (the live obstacle layer, /obstacles: the same grid)
/// holds as kOccupied made occupied; the layer never frees a cell of the map. Throws
/// std::invalid_argument if the two grids differ in size, resolution or origin.
wheelchair_core::OccupancyMap withObstacles(const wheelchair_core::OccupancyMap& map,
                                            const wheelchair_core::OccupancyMap& obstacles);

}  // namespace wheelchair_planner
