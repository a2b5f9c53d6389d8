#include <wheelchair_navigator/navigator_config.h>

namespace wheelchair_navigator {

std::string NavigatorConfig::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.positive("planner_timeout", planner_timeout)
      .positive("safety_clear_timeout", safety_clear_timeout)
      .check(max_planner_retries >= 0, "max_planner_retries must be >= 0")
      .nonNegative("retry_delay", retry_delay)
      .nonNegative("wait_for_clear", wait_for_clear)
      .positive("probe_period", probe_period)
      .nonNegative("clear_confirm", clear_confirm)
      .nonNegative("blocked_timeout", blocked_timeout)
      .positive("replan_period", replan_period)
      .check(max_replans >= 0, "max_replans must be >= 0")
      .nonNegative("block_start", block_start)
      .positive("block_length", block_length)
      .check(block_length > block_start, "block_length must exceed block_start")
      .positive("block_clearance", block_clearance)
      .nonNegative("where_radius", where_radius)
      .positive("start_tolerance", start_tolerance)
      .positive("layer_lookahead", layer_lookahead)
      .positive("layer_corridor", layer_corridor)
      .positive("layer_max_age", layer_max_age)
      .positive("no_progress_timeout", no_progress_timeout)
      .positive("progress_distance", progress_distance)
      .positive("progress_rotation", progress_rotation)
      .check(max_control_retries >= 0, "max_control_retries must be >= 0")
      .positive("stop_timeout", stop_timeout)
      .check(max_back_ups >= 0, "max_back_ups must be >= 0")
      .finite("goal_min_clearance", goal_min_clearance);
  return checks.result();
}

void readNavigatorConfig(wheelchair_core::ConfigReader& reader, NavigatorConfig& c) {
  reader.read("planner_timeout", c.planner_timeout);
  reader.read("safety_clear_timeout", c.safety_clear_timeout);
  reader.read("max_planner_retries", c.max_planner_retries);
  reader.read("retry_delay", c.retry_delay);
  reader.read("wait_for_clear", c.wait_for_clear);
  reader.read("probe_period", c.probe_period);
  reader.read("clear_confirm", c.clear_confirm);
  reader.read("blocked_timeout", c.blocked_timeout);
  reader.read("replan_period", c.replan_period);
  reader.read("max_replans", c.max_replans);
  reader.read("block_start", c.block_start);
  reader.read("block_length", c.block_length);
  reader.read("block_clearance", c.block_clearance);
  reader.read("where_radius", c.where_radius);
  reader.read("start_tolerance", c.start_tolerance);
  reader.read("layer_lookahead", c.layer_lookahead);
  reader.read("layer_corridor", c.layer_corridor);
  reader.read("layer_max_age", c.layer_max_age);
  reader.read("no_progress_timeout", c.no_progress_timeout);
  reader.read("progress_distance", c.progress_distance);
  reader.read("progress_rotation", c.progress_rotation);
  reader.read("max_control_retries", c.max_control_retries);
  reader.read("stop_timeout", c.stop_timeout);
  reader.read("max_back_ups", c.max_back_ups);
  reader.read("goal_min_clearance", c.goal_min_clearance);
}

}  // namespace wheelchair_navigator
