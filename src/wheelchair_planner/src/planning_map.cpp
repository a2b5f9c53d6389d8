#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner/planning_map.h>

#include <cmath>
#include <stdexcept>

namespace wheelchair_planner {

PlanningMap::PlanningMap(const wheelchair_core::OccupancyMap& map, const PlannerSettings& settings)
    : cspace_(map, settings.cspace), checker_(cspace_, settings.footprint) {}

bool PlanningMap::gateFirstStagePath(const FootprintGateParams& gate, const std::string& stage,
                                     const std::string& leaves_cspace, const Pose2D& start,
                                     const Pose2D& goal, std::vector<Pose2D>& plan,
                                     Certificate& cert) const {
  if (!pathIsCollisionFree(cspace_, plan)) {
    cert.failure_reason = leaves_cspace;
    return false;
  }
  cert.path_stage = stage;
  const bool ok = enforceFootprint(checker_, gate, start, goal, plan, cert);
  fillPathFigures(cspace_, plan, cert);
  return ok;
}

wheelchair_core::OccupancyMap withObstacles(const wheelchair_core::OccupancyMap& map,
                                            const wheelchair_core::OccupancyMap& obstacles) {
  if (obstacles.width != map.width || obstacles.height != map.height ||
      std::abs(obstacles.resolution - map.resolution) > 1e-9 * map.resolution ||
      std::abs(obstacles.origin_x - map.origin_x) > 1e-6 ||
      std::abs(obstacles.origin_y - map.origin_y) > 1e-6 ||
      obstacles.origin_yaw != map.origin_yaw || obstacles.data.size() != map.data.size()) {
    throw std::invalid_argument("the obstacle layer's grid is not the map's");
  }
  wheelchair_core::OccupancyMap merged = map;
  for (size_t k = 0; k < merged.data.size(); ++k)
    if (obstacles.data[k] == wheelchair_core::kOccupied)
      merged.data[k] = wheelchair_core::kOccupied;
  return merged;
}

}  // namespace wheelchair_planner
