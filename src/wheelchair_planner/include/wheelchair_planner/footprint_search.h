// Footprint-aware (x, y, heading) search: Hybrid A* with forward motion primitives only
// (straight and arcs; no reversing: the only laser looks forward), an optional in-place rotation
// at the start (the controller rotates at rest before a path), cost = length + a soft-clearance
// penalty, heuristic = the geodesic distance to the goal on the grid. A candidate path counts
// only when its executed sweep (sweep_check.h: the controller's smoothing and the final rotation)
// keeps the hard minimum footprint clearance.
#pragma once

#include <wheelchair_planner/footprint_checker.h>
#include <wheelchair_planner/sweep_check.h>

#include <string>
#include <vector>

namespace wheelchair_planner {

struct FootprintSearchParams {
  double time_limit = 3.0;                        ///< [s] wall time
  std::vector<double> radii{2.0, 1.0, 0.6, 0.4};  ///< arc radii [m], both sides, plus straight
  int heading_bins = 72;                          ///< 5 degrees
  double xy_bin = 0.1;                            ///< [m]
  double min_clearance = 0.05;                    ///< hard footprint clearance [m]
  double soft_clearance = 0.20;                   ///< preferred footprint clearance [m]
  double clearance_weight = 2.0;  ///< cost per metre at the hard minimum, relative to length
  double turn_weight = 0.5;       ///< extra cost per metre per 1/m of curvature
  double rotation_cost = 0.3;     ///< cost of the start rotation [m/rad]
  double goal_tolerance = 0.12;   ///< [m] from where a last straight piece joins the goal
  double goal_join_angle = 0.26;  ///< [rad] that piece within 15 degrees of the arrival heading
  double goal_join_slack = 0.02;  ///< [m] ... unless it is shorter than this
  /// One weighted A* run: heuristic weight (>= 1), the extra hard clearance of the primitives
  /// [m] (the controller's smoothing moves the path by up to ~1 cm at curvature steps; every
  /// candidate's executed sweep is verified anyway) and the primitive length [m].
  struct Attempt {
    double heuristic_weight;
    double margin;
    double step;
  };
  /// Tried in order until one finds a path, each for at most `attempt_expansions`. Through an
  /// 80-85 cm door the lattice (bins, 5 degree headings, step) either lands in the few
  /// centimetres the body has or not, and which setting does changes with a 0.01 rad change of
  /// the start heading (flat, island -> bedroom door, 5 start headings 3.05-3.16: each setting
  /// alone found 1-2; these eight in turn found all, 0.2-2.4 s under load). A success needs
  /// < 2500 expansions. The least greedy first: where it succeeds its paths keep more
  /// clearance and turn wider (Table 2 pair 9: 2.5 first ended in a 0.4 m hook, goal 9 cm off).
  std::vector<Attempt> attempts{{1.5, 0.015, 0.15}, {2.5, 0.005, 0.15}, {2.0, 0.0, 0.15},
                                {2.5, 0.005, 0.20}, {2.0, 0.0, 0.12},   {2.0, 0.0, 0.20},
                                {2.5, 0.005, 0.12}, {3.0, 0.0, 0.15}};
  int attempt_expansions = 3000;  ///< per attempt: deterministic, whatever the machine's load
  int max_candidates = 200;       ///< goal-region arrivals whose sweep is verified
};

struct FootprintSearchResult {
  bool found = false;
  std::vector<Pose2D> path;  ///< start position ... goal (goal heading on the last pose)
  SweepCheck sweep;          ///< the found path's executed sweep, verified
  size_t expansions = 0;
  double time = 0.0;   ///< [s]
  std::string reason;  ///< on failure
};

/// Tries params.attempts in order (each a weighted A* run, search_attempt.h) within
/// params.time_limit until one finds a path whose executed sweep (`sweep`) passes.
FootprintSearchResult footprintSearch(const FootprintChecker& checker, const Pose2D& start,
                                      const Pose2D& goal, const FootprintSearchParams& params,
                                      const SweepModel& sweep = SweepModel());

}  // namespace wheelchair_planner
