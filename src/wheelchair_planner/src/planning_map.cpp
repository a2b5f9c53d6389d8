#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner/planning_map.h>

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

}  // namespace wheelchair_planner
