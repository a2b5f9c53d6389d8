#include <wheelchair_controller/smooth_path.h>
#include <wheelchair_harmonic_planner/sweep.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace wheelchair_harmonic_planner {

std::vector<Pose2D> rotationInPlace(double x, double y, double yaw0, double yaw1, double max_turn) {
  const double delta = std::remainder(yaw1 - yaw0, 2.0 * M_PI);
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / max_turn)));
  std::vector<Pose2D> out;
  for (int k = 0; k <= n; ++k) out.push_back({x, y, yaw0 + delta * k / n});
  return out;
}

std::vector<SweepPose> executedSweep(const Pose2D& start, const std::vector<Pose2D>& plan,
                                     const SweepParams& params) {
  std::vector<SweepPose> sweep;
  std::vector<wheelchair_controller::Pose2> poses;
  for (const Pose2D& p : plan) poses.emplace_back(p.x, p.y, p.yaw);
  std::unique_ptr<wheelchair_controller::SmoothPath> path;
  try {
    path = std::make_unique<wheelchair_controller::SmoothPath>(poses);  // the controller's own
  } catch (const std::invalid_argument&) {
    return sweep;  // the controller refuses it (and stops)
  }
  const auto first = path->at(0.0);
  // The controller rotates in place at rest when the heading is off by more than its tolerance
  // (0.5 rad); below it the chair turns while it drives off, sweeping about the same poses.
  for (const Pose2D& p :
       rotationInPlace(start.x, start.y, start.yaw, first.heading, params.max_turn))
    sweep.push_back({p, SweepPose::Phase::kStartRotation});
  const double length = path->length();
  auto bodyAt = [&](double s) {
    const auto q = path->at(s);
    return Pose2D{q.position.x(), q.position.y(), q.heading};
  };
  Pose2D prev = bodyAt(0.0);
  sweep.push_back({prev, SweepPose::Phase::kPath});
  const int steps = std::max(1, static_cast<int>(std::ceil(length / params.max_step)));
  for (int i = 1; i <= steps; ++i) {
    const double s0 = length * (i - 1) / steps, s1 = length * i / steps;
    const Pose2D next = bodyAt(s1);
    const int sub =
        std::max(1, static_cast<int>(std::ceil(std::abs(next.yaw - prev.yaw) / params.max_turn)));
    for (int k = 1; k <= sub; ++k)
      sweep.push_back({bodyAt(s0 + (s1 - s0) * k / sub), SweepPose::Phase::kPath});
    prev = next;
  }
  if (std::abs(std::remainder(path->goalHeading() - prev.yaw, 2.0 * M_PI)) >
      params.goal_heading_tolerance) {
    for (const Pose2D& p :
         rotationInPlace(prev.x, prev.y, prev.yaw, path->goalHeading(), params.max_turn))
      sweep.push_back({p, SweepPose::Phase::kGoalRotation});
  }
  return sweep;
}

namespace {

const char* phaseName(SweepPose::Phase phase) {
  switch (phase) {
    case SweepPose::Phase::kStartRotation:
      return "rotating in place at the start";
    case SweepPose::Phase::kGoalRotation:
      return "rotating in place to the goal heading";
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
  // Far from obstacles only a lower bound is computed (the enclosing disc is clear).
  const double enough = rule.min_clearance + 0.25;
  for (const SweepPose& sp : sweep) {
    const FootprintContact c = checker.clearance(sp.pose, -1e9, enough);
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
       << " with base_link at (" << violation_pose.x << ", " << violation_pose.y << ", yaw "
       << violation_pose.yaw << "): footprint clearance " << violation.clearance << " m, minimum "
       << worst_required << " m";
    result.reason = os.str();
  }
  return result;
}

}  // namespace wheelchair_harmonic_planner
