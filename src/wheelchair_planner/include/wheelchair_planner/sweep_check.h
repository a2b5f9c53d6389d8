// The footprint clearance of the motion the controller will drive for a plan: the poses come
// from the controller itself (wheelchair_controller::executedSweep: its smoothing, phases and
// tolerances), so the gate and the controller cannot drift apart; checked here with the
// footprint, this is what the body sweeps.
#pragma once

#include <wheelchair_controller/driven_motion.h>
#include <wheelchair_controller/tracker_config.h>
#include <wheelchair_planner/footprint_checker.h>

#include <string>
#include <vector>

namespace wheelchair_planner {

using wheelchair_controller::SweepPose;

/// How the gate obtains the motion it checks: the controller's configuration (its start and goal
/// heading tolerances decide the in-place rotations) and how finely the motion is sampled.
struct SweepModel {
  wheelchair_controller::TrackerConfig controller;
  wheelchair_controller::SweepSampling sampling;

  /// Poses of base_link from `start` (the chair's pose, yaw included) along `plan` (first pose
  /// at the start position, last pose with the goal heading); empty if the controller would
  /// refuse the plan.
  std::vector<SweepPose> sweep(const Pose2D& start, const std::vector<Pose2D>& plan) const {
    return wheelchair_controller::executedSweep(start, plan, controller, sampling);
  }
};

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
  /// Smallest footprint clearance per piece of the plan (split at its cusps; a turn in place
  /// before a piece counts to it) [m].
  std::vector<double> piece_clearance;
  size_t poses = 0;    ///< number of poses checked
  std::string reason;  ///< on failure: where the body would hit, one line
};

/// Footprint clearance of every sweep pose; ok if each keeps what `rule` requires there.
SweepCheck checkSweep(const FootprintChecker& checker, const std::vector<SweepPose>& sweep,
                      const ClearanceRule& rule);

}  // namespace wheelchair_planner
