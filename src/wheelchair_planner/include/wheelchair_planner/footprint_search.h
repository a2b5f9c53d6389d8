// Footprint-aware (x, y, heading) search: Hybrid A* with forward and reverse motion primitives
// (straight and arcs either way, Reeds-Shepp-like as in Nav2's Smac Hybrid-A*), an optional
// in-place rotation at the start (the controller rotates at rest before a path), cost = length +
// a soft-clearance penalty, reversed metres weighted by reverse_cost, each cusp (stop, change of
// direction) cusp_cost, at most max_cusps cusps and max_reverse_length reversed; heuristic = the
// geodesic distance to the goal on the grid. The path's poses carry the chair's heading, so its
// reverse pieces face against their motion (wheelchair_core/path_direction.h). A candidate path
// counts only when its executed sweep (sweep_check.h: the controller's smoothing, its stops and
// turns at the cusps and the final rotation) keeps the hard minimum footprint clearance. The
// lattice settings share one budget (time and expansions), used to the end.
#pragma once

#include <wheelchair_planner/footprint_checker.h>
#include <wheelchair_planner/sweep_check.h>

#include <string>
#include <vector>

namespace wheelchair_planner {

struct FootprintSearchParams {
  double time_limit = 3.0;          ///< [s] wall time, the whole search (every setting)
  int max_expansions = 200000;      ///< the whole search (every setting)
  bool reverse = true;              ///< reverse primitives (the chair senses behind itself)
  double reverse_cost = 2.0;        ///< cost of a reversed metre relative to a forward one
  double cusp_cost = 1.0;           ///< [m] cost of each cusp
  int max_cusps = 3;                ///< direction changes per path
  double max_reverse_length = 5.0;  ///< [m] reversed per path
  /// Analytic expansion: from nodes within analytic_distance [m] (geodesic) of the goal, the
  /// shortest Reeds-Shepp path to the goal pose with turning radius analytic_radius [m] is
  /// tried; it reaches the goal heading exactly (where the final rotation would hit).
  double analytic_distance = 3.0;
  double analytic_radius = 0.5;
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
  /// `backward`: the run searches from the goal to the start and its path is driven the other
  /// way round (a way out of a room is a way in, reversed: entering a side room through its
  /// door is what a forward search finds quickly, leaving it backwards is not); its primitives
  /// are costed, limited and verified as they will be driven.
  /// `one_slice`: the run gets the first round's slice only (a lucky alignment of the lattice
  /// with a door is found within one slice or not at all; later rounds go to the others).
  struct Attempt {
    double heuristic_weight;
    double margin;
    double step;
    bool backward = false;
    bool one_slice = false;
  };
  /// Tried in order, each for `attempt_expansions` (a slice); then, while the budget lasts, each
  /// that can go on (not `one_slice`) gets another slice in turn, until one finds a path; from
  /// the second round on the forward and backward runs also join their trees where they meet
  /// (same 10 cm cell, heading within a bin or two, joined by a short straight piece along the
  /// motion). Through an 80-85 cm door the lattice (bins, 5 degree headings, step) either lands
  /// in the few centimetres the body has or not, and which setting does changes with a 0.01 rad
  /// change of the start heading (flat, island -> bedroom door, 5 start headings 3.05-3.16:
  /// each setting alone found 1-2; the eight forward settings in turn found all): a success
  /// there needs < 2500 expansions, so six of them get one slice. The least greedy first: where
  /// it succeeds its paths keep more clearance and turn wider (Table 2 pair 9: 2.5 first ended
  /// in a 0.4 m hook, goal 9 cm off). The last two, a greedy pair one run each way, go on:
  /// leaving a side room of flat (the study, the bathroom, parked facing into it) takes them a
  /// few 10^4 expansions together and was not found in 200 000 by the forward settings alone
  /// (issue 24).
  std::vector<Attempt> attempts{{1.5, 0.015, 0.15},
                                {2.5, 0.005, 0.15, false, true},
                                {2.0, 0.0, 0.15, false, true},
                                {2.5, 0.005, 0.20, false, true},
                                {2.0, 0.0, 0.12, false, true},
                                {2.0, 0.0, 0.20, false, true},
                                {2.5, 0.005, 0.12, false, true},
                                {3.0, 0.005, 0.15},
                                {3.0, 0.005, 0.15, true}};
  int attempt_expansions = 3000;  ///< per slice: deterministic, whatever the machine's load
  int max_candidates = 200;       ///< goal-region arrivals whose sweep is verified
};

struct FootprintSearchResult {
  bool found = false;
  std::vector<Pose2D> path;      ///< start position ... goal (goal heading on the last pose)
  SweepCheck sweep;              ///< the found path's executed sweep, verified
  int cusps = 0;                 ///< direction changes of the found path
  double reversed_length = 0.0;  ///< [m] of the found path's primitives driven in reverse
  size_t expansions = 0;
  double time = 0.0;   ///< [s]
  std::string reason;  ///< on failure: what was tried, why it ended, where the body would hit
};

/// Runs params.attempts (each a weighted A* run, search_attempt.h) in slices on one budget
/// (params.time_limit, params.max_expansions) until one finds a path whose executed sweep
/// (`sweep`) passes, or every setting has explored all it reaches, or the budget is spent.
FootprintSearchResult footprintSearch(const FootprintChecker& checker, const Pose2D& start,
                                      const Pose2D& goal, const FootprintSearchParams& params,
                                      const SweepModel& sweep = SweepModel());

}  // namespace wheelchair_planner
