// The navigator's settings (the one parameter pattern of wheelchair_core/config.h): defaults
// here, validate(), and readNavigatorConfig() naming every key. Times are in the clock the
// navigator is driven with (simulated time in the simulator).
#pragma once

#include <wheelchair_core/config.h>

#include <string>

namespace wheelchair_navigator {

struct NavigatorConfig {
  // Starting.
  double planner_timeout = 30.0;      ///< [s] a route not answered by then: not ready
  double safety_clear_timeout = 2.0;  ///< [s] the supervisor must allow motion within this
  int max_planner_retries = 1;        ///< a failed first route is asked again (stale pose...)
  double retry_delay = 1.0;           ///< [s] before a retry
  // Something in the way.
  double wait_for_clear = 5.0;    ///< [s] stopped for it: wait this long before a way around
  double probe_period = 1.0;      ///< [s] how often the supervisor is asked if the way is free
  double clear_confirm = 1.0;     ///< [s] the way stays free this long before the chair goes on
  double blocked_timeout = 60.0;  ///< [s] no way around: wait this long, then end the drive
  double replan_period = 5.0;     ///< [s] while blocked: ask for a way around this often
  int max_replans = 10;           ///< routes per drive after the first one
  double block_start = 0.5;       ///< [m] ahead of the stopped chair, along its route: the
  double block_length = 1.5;      ///< [m]   stretch the obstacle blocks (stop distance + braking)
  double block_clearance = 0.3;   ///< [m] a route this close to that stretch goes through it
  double where_radius = 3.0;      ///< [m] the nearest named place within it says where
  /// [m] a route handed over while the chair stands (waiting, blocked) starts this close to
  /// where it stands, or it is asked again from there: the planner checked the body's motion
  /// (a turn on the spot first) from the route's start, not from where the chair stopped later.
  double start_tolerance = 0.10;
  // The obstacle layer (/obstacles) on the route ahead, while driving.
  double layer_lookahead = 3.0;  ///< [m] along the route
  double layer_corridor = 0.35;  ///< [m] either side of the route (chair half width + margin)
  double layer_max_age = 2.0;    ///< [s] an older layer is not read
  // Progress and control.
  double no_progress_timeout = 30.0;  ///< [s] without progress: the drive ends
  double progress_distance = 0.10;    ///< [m] closer to the goal along the route is progress
  double progress_rotation = 0.30;    ///< [rad] turned on the spot is progress
  int max_control_retries = 2;        ///< the controller gave up: new routes from where it is
  double stop_timeout = 5.0;          ///< [s] a controlled stop not reported by then: result anyway
  int max_back_ups = 1;               ///< back-up recoveries per drive (when a back-up hook is set)
  // The goal.
  double goal_min_clearance = 0.0;  ///< [m] the body at the goal closer than this: no room

  /// "" if usable, else every problem.
  std::string validate() const;
};

/// Every key of NavigatorConfig, named as its field.
void readNavigatorConfig(wheelchair_core::ConfigReader& reader, NavigatorConfig& config);

}  // namespace wheelchair_navigator
