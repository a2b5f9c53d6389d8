// The footprint gate shared by every planner plugin: the plan's executed sweep (sweep_check.h,
// the controller's own motion) must keep the hard minimum footprint clearance; if it does not,
// the footprint search (footprint_search.h) replaces it; if that finds nothing, the plan fails
// with the place where the body would hit. No plugin hands the controller a plan whose sweep
// collides.
#pragma once

#include <wheelchair_planner/certificate.h>
#include <wheelchair_planner/footprint_checker.h>
#include <wheelchair_planner/footprint_search.h>
#include <wheelchair_planner/sweep_check.h>

#include <string>
#include <vector>

namespace wheelchair_planner {

struct FootprintGateParams {
  bool repair = true;  ///< run the footprint search when the first path's sweep fails
  /// The search's time limit, goal tolerance and lattice; its hard and soft clearance are the
  /// C-space's min_clearance and clearance_band (set by the gate).
  FootprintSearchParams search;
  SweepModel sweep;  ///< the controller's motion for a plan

  std::string validate() const;
};

/// Checks `plan` (from `start`, the chair's pose) as the controller will execute it, with the
/// C-space's `min_clearance` and `clearance_band`. On success the plan is the first stage's or
/// the footprint search's (certificate: path_stage, footprint figures); on failure
/// `cert.failure_reason` says where the body would hit.
bool enforceFootprint(const FootprintChecker& checker, const FootprintGateParams& params,
                      const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                      Certificate& cert);

}  // namespace wheelchair_planner
