// The footprint gate shared by every planner plugin: the plan's executed sweep (sweep.h) must
// keep the hard minimum footprint clearance; if it does not, the footprint search
// (footprint_search.h) replaces it; if that finds nothing, the plan fails with the place where
// the body would hit. No plugin hands the controller a plan whose sweep collides.
#pragma once

#include <wheelchair_harmonic_planner/config_space.h>
#include <wheelchair_harmonic_planner/footprint.h>
#include <wheelchair_harmonic_planner/footprint_search.h>
#include <wheelchair_harmonic_planner/global_planner.h>
#include <wheelchair_harmonic_planner/sweep.h>

#include <vector>

namespace wheelchair_harmonic_planner {

struct FootprintPlanningParams {
  std::vector<Vertex> footprint;  ///< base_link polygon [m]
  bool repair = true;             ///< run the footprint search when the first path's sweep fails
  FootprintSearchParams search;
  SweepParams sweep;
};

/// Reads `footprint` ("x,y;x,y;...", default: wheelchair_description's chair.yaml),
/// `footprint_repair`, `footprint_search_time`, `footprint_goal_tolerance` (search) and takes
/// min_clearance / clearance_band from the C-space parameters.
FootprintPlanningParams footprintPlanningParams(const ParameterMap& params,
                                                const ConfigSpaceParams& cspace_params);

/// Checks `plan` (from `start`, the chair's pose) as the controller will execute it. On
/// success the plan is the first stage's or the footprint search's (certificate: path_stage,
/// footprint figures); on failure `cert.failure_reason` says where the body would hit.
bool enforceFootprint(const FootprintChecker& checker, const FootprintPlanningParams& params,
                      const Pose2D& start, const Pose2D& goal, std::vector<Pose2D>& plan,
                      Certificate& cert);

}  // namespace wheelchair_harmonic_planner
