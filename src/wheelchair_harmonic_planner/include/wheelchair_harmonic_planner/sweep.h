// The poses the chair's body takes when the controller (wheelchair_controller) executes a plan:
// an in-place rotation at the start from the chair's heading to the smoothed path's tangent,
// the path as the controller smooths it (its own SmoothPath) with the tangent heading (the
// controller keeps the axle on that path, off-tracking compensated), and the in-place rotation
// to the goal heading. Checked with the footprint, this is what the body sweeps.
#pragma once

#include <wheelchair_harmonic_planner/footprint.h>
#include <wheelchair_harmonic_planner/plan_types.h>

#include <cmath>
#include <string>
#include <vector>

namespace wheelchair_harmonic_planner {

struct SweepParams {
  double max_step = 0.02;                ///< [m] between sweep poses along the path
  double max_turn = 2.0 * M_PI / 180.0;  ///< [rad] between sweep poses
  double goal_heading_tolerance = 0.05;  ///< [rad] controller: no final rotation below this
};

/// One pose of the sweep and the phase it belongs to.
struct SweepPose {
  enum class Phase { kStartRotation, kPath, kGoalRotation };
  Pose2D pose;
  Phase phase = Phase::kPath;
};

/// Poses of base_link from `start` (the chair's current pose, yaw included) along `plan` (first
/// pose at the start position, last pose with the goal heading). Empty if the controller would
/// refuse the plan (empty, non-finite, zero length).
std::vector<SweepPose> executedSweep(const Pose2D& start, const std::vector<Pose2D>& plan,
                                     const SweepParams& params = SweepParams());

/// Poses of an in-place rotation about (x, y) from yaw0 to yaw1 the short way, at most
/// `max_turn` apart, both ends included.
std::vector<Pose2D> rotationInPlace(double x, double y, double yaw0, double yaw1, double max_turn);

/// The hard minimum footprint clearance, relaxed only near the start: the chair may already
/// stand closer than the minimum (parked by a table) and must be able to leave; there (start
/// rotation, and within `start_radius` of the start) the requirement is its own clearance at
/// the start less 5 mm. A start in contact (<= 0) allows nothing.
struct ClearanceRule {
  double min_clearance = 0.05;  ///< [m]
  Pose2D start;
  double start_clearance = 1e9;  ///< footprint clearance at the start pose [m]
  double start_radius = 0.5;     ///< [m]
  double required(const Pose2D& pose, bool start_rotation) const;
};

/// The rule for a plan from `start`.
ClearanceRule clearanceRule(const FootprintChecker& checker, const Pose2D& start,
                            double min_clearance);

struct SweepCheck {
  bool ok = false;             ///< every pose keeps at least the required clearance
  double min_clearance = 0.0;  ///< smallest footprint clearance along the sweep [m]
  FootprintContact contact;    ///< where the body comes closest
  Pose2D worst_pose;           ///< the body pose there
  SweepPose::Phase worst_phase = SweepPose::Phase::kPath;
  size_t poses = 0;    ///< number of poses checked
  std::string reason;  ///< on failure: where the body would hit, one line
};

/// Footprint clearance of every sweep pose; ok if each keeps what `rule` requires there.
SweepCheck checkSweep(const FootprintChecker& checker, const std::vector<SweepPose>& sweep,
                      const ClearanceRule& rule);

}  // namespace wheelchair_harmonic_planner
