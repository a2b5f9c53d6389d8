#include <wheelchair_navigator/goal_check.h>
#include <wheelchair_planner/config_space.h>
#include <wheelchair_planner/footprint_checker.h>

#include <cstdio>

namespace wheelchair_navigator {

namespace {

std::string where(const wheelchair_core::Pose2D& goal) {
  char text[64];
  std::snprintf(text, sizeof(text), "goal (%.2f, %.2f)", goal.x, goal.y);
  return text;
}

}  // namespace

GoalCheck::GoalCheck(const wheelchair_core::OccupancyMap& map,
                     const wheelchair_core::Polygon& footprint, double inscribed_radius) {
  wheelchair_planner::ConfigSpaceParams params;
  params.inscribed_radius = inscribed_radius;
  params.min_clearance = 0.0;  // the C-space is only the distance field here
  params.clearance_band = 0.0;
  cspace_ = std::make_unique<wheelchair_planner::ConfigSpace>(map, params);
  checker_ = std::make_unique<wheelchair_planner::FootprintChecker>(*cspace_, footprint);
}

GoalCheck::~GoalCheck() = default;

std::optional<GoalRefusal> GoalCheck::check(const wheelchair_core::Pose2D& goal,
                                            double min_clearance) const {
  int ix, iy;
  if (!cspace_->worldToCell(goal.x, goal.y, ix, iy))
    return GoalRefusal{Reason::kGoalOutsideMap, where(goal) + " is outside the map"};
  if (cspace_->obstacleDistance(ix, iy) <= 0.0)
    return GoalRefusal{Reason::kGoalInObstacle,
                       where(goal) + " is in an occupied or unknown cell of the map"};
  const wheelchair_planner::FootprintContact contact = checker_->clearance(goal);
  if (contact.clearance < min_clearance) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  ": the chair's body there has %.2f m clearance (minimum %.2f m) at (%.2f, %.2f)",
                  contact.clearance, min_clearance, contact.x, contact.y);
    return GoalRefusal{Reason::kGoalNoRoom, where(goal) + text};
  }
  return std::nullopt;
}

}  // namespace wheelchair_navigator
