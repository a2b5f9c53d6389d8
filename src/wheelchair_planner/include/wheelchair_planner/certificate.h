// The plan certificate every planner plugin fills (ROS-free; the host publishes it as
// wheelchair_msgs/PlanCertificate). Plans are wheelchair_core::Pose2D in the map frame.
#pragma once

#include <wheelchair_core/pose2d.h>

#include <string>
#include <vector>

namespace wheelchair_planner {

using wheelchair_core::Pose2D;

/// What a plan proves about itself (issue 7): filled by every planner, published with the path.
struct Certificate {
  bool success = false;
  std::string planner;         ///< plugin name, e.g. "HarmonicPlanner" or "OmplPlanner/RRTstar"
  std::string failure_reason;  ///< empty on success; one line naming the cause otherwise
  // Solver (harmonic planner only; zero for sampling planners).
  int solver_iterations = 0;
  double solver_residual = 0.0;  ///< max relative residual of the discrete Laplace equation
  bool solver_converged = false;
  bool warm_started = false;
  // Descent (harmonic planner only).
  bool descent_reached_goal = false;
  int plateau_steps = 0;      ///< descent steps whose potential did not improve
  double min_gradient = 0.0;  ///< smallest |grad log u| along the path [1/m]
  // Path quality.
  double length = 0.0;         ///< [m]
  double max_curvature = 0.0;  ///< [1/m], from consecutive headings
  double min_clearance = 0.0;  ///< distance beyond the inscribed circle to the nearest obstacle [m]
  double min_clearance_x = 0.0;  ///< where the minimum clearance occurs [m]
  double min_clearance_y = 0.0;
  std::vector<double> clearance;  ///< clearance profile, one value per plan pose [m]
  double planning_time = 0.0;     ///< wall time of makePlan [s]
  // Footprint (footprint_gate.h): the plan's executed sweep with the chair's polygon.
  std::string path_stage;              ///< "harmonic", "ompl" or "footprint_search"
  bool footprint_checked = false;      ///< the sweep was checked with the footprint
  double footprint_clearance = 0.0;    ///< smallest footprint clearance along the sweep [m]
  double footprint_clearance_x = 0.0;  ///< the body point where it occurs [m]
  double footprint_clearance_y = 0.0;
  int sweep_poses = 0;            ///< poses checked (<= 2 cm / 2 degrees apart)
  std::string first_stage_sweep;  ///< why the first stage's path failed its sweep, if it did
  int search_expansions = 0;      ///< footprint search nodes expanded (0: not run)
  double search_time = 0.0;       ///< [s]
  // Direction (wheelchair_core/path_direction.h): the plan split at its cusps.
  int cusps = 0;                          ///< changes of direction (the chair stops at each)
  double reversed_length = 0.0;           ///< [m] driven in reverse
  std::vector<bool> segment_reverse;      ///< per piece: driven in reverse
  std::vector<double> segment_clearance;  ///< per piece: smallest footprint clearance [m]
};

}  // namespace wheelchair_planner
