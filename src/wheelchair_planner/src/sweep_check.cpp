#include <wheelchair_planner/sweep_check.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace wheelchair_planner {

namespace {

const char* phaseName(SweepPose::Phase phase) {
  switch (phase) {
    case SweepPose::Phase::kStartRotation:
      return "rotating in place at the start";
    case SweepPose::Phase::kGoalRotation:
      return "rotating in place to the goal heading";
    case SweepPose::Phase::kCuspRotation:
      return "turning in place where it changes direction";
    default:
      return "following the path";
  }
}

}  // namespace

double ClearanceRule::required(const Pose2D& pose, bool start_rotation) const {
  const bool near_start =
      start_rotation || std::hypot(pose.x - start.x, pose.y - start.y) < start_radius;
  if (!near_start || start_clearance >= min_clearance) return min_clearance;
  return start_clearance > 0.0 ? start_clearance - 0.005 : 1e-9;
}

ClearanceRule clearanceRule(const FootprintChecker& checker, const Pose2D& start,
                            double min_clearance) {
  ClearanceRule rule;
  rule.min_clearance = min_clearance;
  rule.start = start;
  rule.start_clearance = checker.clearance(start).clearance;
  return rule;
}

SweepCheck checkSweep(const FootprintChecker& checker, const std::vector<SweepPose>& sweep,
                      const ClearanceRule& rule) {
  SweepCheck result;
  result.min_clearance = 1e9;
  double worst_margin = 1e9, worst_required = rule.min_clearance;
  FootprintContact violation;
  Pose2D violation_pose;
  SweepPose::Phase violation_phase = SweepPose::Phase::kPath;
  bool violation_reverse = false;
  // Far from obstacles only a lower bound is computed (the enclosing disc is clear).
  const double enough = rule.min_clearance + 0.25;
  for (const SweepPose& sp : sweep) {
    const FootprintContact c = checker.clearance(sp.pose, -1e9, enough);
    if (sp.piece >= static_cast<int>(result.piece_clearance.size()))
      result.piece_clearance.resize(sp.piece + 1, 1e9);
    result.piece_clearance[sp.piece] = std::min(result.piece_clearance[sp.piece], c.clearance);
    if (c.clearance < result.min_clearance) {
      result.min_clearance = c.clearance;
      result.contact = c;
      result.worst_pose = sp.pose;
      result.worst_phase = sp.phase;
    }
    const double required = rule.required(sp.pose, sp.phase == SweepPose::Phase::kStartRotation);
    if (c.clearance - required < worst_margin) {
      worst_margin = c.clearance - required;
      worst_required = required;
      violation = c;
      violation_pose = sp.pose;
      violation_phase = sp.phase;
      violation_reverse = sp.direction == wheelchair_core::Direction::kReverse;
    }
  }
  result.poses = sweep.size();
  result.ok = !sweep.empty() && worst_margin >= 0.0;
  if (sweep.empty()) {
    result.min_clearance = 0.0;
    result.reason = "the controller would refuse the plan (empty or zero length)";
  } else if (!result.ok) {
    std::ostringstream os;
    os.precision(3);
    os << "the chair's body would "
       << (violation.clearance <= 0.0 ? "hit an obstacle" : "come too close to an obstacle")
       << " at (" << violation.x << ", " << violation.y << ") while " << phaseName(violation_phase)
       << (violation_reverse && violation_phase == SweepPose::Phase::kPath ? " in reverse" : "")
       << " with base_link at (" << violation_pose.x << ", " << violation_pose.y << ", yaw "
       << violation_pose.yaw << "): footprint clearance " << violation.clearance << " m, minimum "
       << worst_required << " m";
    result.reason = os.str();
  }
  return result;
}

}  // namespace wheelchair_planner
