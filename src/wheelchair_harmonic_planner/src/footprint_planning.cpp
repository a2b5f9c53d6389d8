#include <wheelchair_description/chair_params.h>
#include <wheelchair_harmonic_planner/footprint_planning.h>
#include <wheelchair_harmonic_planner/path_metrics.h>

#include <sstream>

namespace wheelchair_harmonic_planner {

FootprintPlanningParams footprintPlanningParams(const ParameterMap& params,
                                                const ConfigSpaceParams& cspace_params) {
  FootprintPlanningParams p;
  const std::string text = getParam(params, "footprint", std::string());
  if (!text.empty()) {
    p.footprint = parseFootprint(text);
  } else {
    for (const auto& v :
         wheelchair_description::loadChairParams(WHEELCHAIR_PLANNER_DEFAULT_CHAIR_FILE).footprint)
      p.footprint.push_back({v.x(), v.y()});
  }
  p.repair = getParam(params, "footprint_repair", p.repair);
  p.search.time_limit = getParam(params, "footprint_search_time", p.search.time_limit);
  p.search.goal_tolerance = getParam(params, "footprint_goal_tolerance", p.search.goal_tolerance);
  p.search.min_clearance = cspace_params.min_clearance;
  p.search.soft_clearance = std::max(cspace_params.clearance_band, cspace_params.min_clearance);
  if (!(p.search.time_limit > 0.0) || !(p.search.goal_tolerance > 0.0))
    throw std::invalid_argument("footprint_search_time and footprint_goal_tolerance must be > 0");
  return p;
}

namespace {

void recordSweep(const SweepCheck& check, Certificate& cert) {
  cert.footprint_checked = true;
  cert.footprint_clearance = check.min_clearance;
  cert.footprint_clearance_x = check.contact.x;
  cert.footprint_clearance_y = check.contact.y;
  cert.sweep_poses = static_cast<int>(check.poses);
}

}  // namespace

bool enforceFootprint(const FootprintChecker& checker, const FootprintPlanningParams& params,
                      const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                      Certificate& cert) {
  const ClearanceRule rule = clearanceRule(checker, start, params.search.min_clearance);
  const FootprintContact at_goal = checker.clearance(goal);
  if (at_goal.clearance < params.search.min_clearance) {
    std::ostringstream os;
    os.precision(3);
    os << "at the goal (" << goal.x << ", " << goal.y << ", yaw " << goal.yaw
       << ") the chair's body would be " << at_goal.clearance << " m from an obstacle at ("
       << at_goal.x << ", " << at_goal.y << "), minimum " << params.search.min_clearance << " m";
    cert.failure_reason = os.str();
    cert.footprint_checked = true;
    cert.footprint_clearance = at_goal.clearance;
    cert.footprint_clearance_x = at_goal.x;
    cert.footprint_clearance_y = at_goal.y;
    return false;
  }
  const SweepCheck first = checkSweep(checker, executedSweep(start, plan, params.sweep), rule);
  recordSweep(first, cert);
  if (first.ok) return true;
  cert.first_stage_sweep = first.reason;
  if (!params.repair) {
    cert.failure_reason = first.reason;
    return false;
  }
  FootprintSearchResult found = footprintSearch(checker, start, goal, params.search, params.sweep);
  cert.search_expansions = static_cast<int>(found.expansions);
  cert.search_time = found.time;
  if (!found.found) {
    cert.failure_reason = cert.path_stage + " path: " + first.reason + "; " + found.reason;
    return false;
  }
  plan = std::move(found.path);
  cert.path_stage = "footprint_search";
  recordSweep(found.sweep, cert);
  return true;
}

}  // namespace wheelchair_harmonic_planner
