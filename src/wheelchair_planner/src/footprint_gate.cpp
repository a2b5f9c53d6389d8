#include <wheelchair_planner/footprint_gate.h>

#include <wheelchair_core/path_direction.h>

#include <algorithm>
#include <sstream>

namespace wheelchair_planner {

std::string FootprintGateParams::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.positive("footprint_search_time", search.time_limit)
      .positive("footprint_goal_tolerance", search.goal_tolerance)
      .check(search.max_expansions > 0, "footprint_search_expansions must be positive")
      .check(search.max_cusps >= 0, "footprint_max_cusps must be >= 0")
      .nonNegative("footprint_max_reverse_length", search.max_reverse_length)
      .check(search.reverse_cost >= 1.0,
             "footprint_reverse_cost must be >= 1 (forwards is preferred)")
      .nonNegative("footprint_cusp_cost", search.cusp_cost);
  const std::string controller = sweep.controller.validate();
  checks.check(controller.empty(), controller);
  return checks.result();
}

namespace {

void recordSweep(const SweepCheck& check, const std::vector<Pose2D>& plan, Certificate& cert) {
  cert.footprint_checked = true;
  cert.footprint_clearance = check.min_clearance;
  cert.footprint_clearance_x = check.contact.x;
  cert.footprint_clearance_y = check.contact.y;
  cert.sweep_poses = static_cast<int>(check.poses);
  cert.cusps = static_cast<int>(wheelchair_core::cuspCount(plan));
  cert.reversed_length = wheelchair_core::reversedLength(plan);
  cert.segment_reverse.clear();
  for (const wheelchair_core::PathPiece& piece : wheelchair_core::splitAtCusps(plan))
    cert.segment_reverse.push_back(piece.direction == wheelchair_core::Direction::kReverse);
  cert.segment_clearance = check.piece_clearance;
}

}  // namespace

bool enforceFootprint(const FootprintChecker& checker, const FootprintGateParams& params,
                      const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                      Certificate& cert) {
  const ConfigSpaceParams& cspace = checker.configSpace().params();
  FootprintSearchParams search = params.search;
  search.min_clearance = cspace.min_clearance;
  search.soft_clearance = std::max(cspace.clearance_band, cspace.min_clearance);
  const ClearanceRule rule = clearanceRule(checker, start, search.min_clearance);
  const FootprintContact at_goal = checker.clearance(goal);
  if (at_goal.clearance < search.min_clearance) {
    std::ostringstream os;
    os.precision(3);
    os << "at the goal (" << goal.x << ", " << goal.y << ", yaw " << goal.yaw
       << ") the chair's body would be " << at_goal.clearance << " m from an obstacle at ("
       << at_goal.x << ", " << at_goal.y << "), minimum " << search.min_clearance << " m";
    cert.failure_reason = os.str();
    cert.footprint_checked = true;
    cert.footprint_clearance = at_goal.clearance;
    cert.footprint_clearance_x = at_goal.x;
    cert.footprint_clearance_y = at_goal.y;
    return false;
  }
  const SweepCheck first = checkSweep(checker, params.sweep.sweep(start, plan), rule);
  recordSweep(first, plan, cert);
  if (first.ok) return true;
  cert.first_stage_sweep = first.reason;
  if (!params.repair) {
    cert.failure_reason = first.reason;
    return false;
  }
  FootprintSearchResult found = footprintSearch(checker, start, goal, search, params.sweep);
  cert.search_expansions = static_cast<int>(found.expansions);
  cert.search_time = found.time;
  if (!found.found) {
    cert.failure_reason = cert.path_stage + " path: " + first.reason + "; " + found.reason;
    return false;
  }
  plan = std::move(found.path);
  cert.path_stage = "footprint_search";
  recordSweep(found.sweep, plan, cert);
  return true;
}

}  // namespace wheelchair_planner
