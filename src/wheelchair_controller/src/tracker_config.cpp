#include <wheelchair_controller/tracker_config.h>

namespace wheelchair_controller {

namespace {

void checkLimits(wheelchair_core::ConfigChecks& checks, const std::string& name,
                 const MotionLimits& limits, bool speed_needed = true) {
  if (speed_needed) checks.positive((name + " speed").c_str(), limits.speed);
  checks.positive((name + " accel").c_str(), limits.accel);
  checks.positive((name + " jerk").c_str(), limits.jerk);
}

}  // namespace

std::string TrackerConfig::validate() const {
  wheelchair_core::ConfigChecks checks;
  checks.positive("natural_frequency", natural_frequency)
      .positive("damping", damping)
      .positive("max_feedback_accel", max_feedback_accel);
  checkLimits(checks, "path", path_limits.longitudinal);
  checks.positive("lateral_accel", path_limits.lateral_accel)
      .positive("lateral_jerk", path_limits.lateral_jerk)
      .positive("yaw_rate", path_limits.yaw_rate)
      .check(limit_margin > 0.0 && limit_margin <= 1.0, "limit_margin must lie in (0, 1]");
  checkLimits(checks, "rotation", rotation_limits);
  checkLimits(checks, "start offset", start_offset_limits, false);
  checks.positive("reverse_lookahead", reverse_lookahead)
      .check(reverse_max_speed > 0.0 && reverse_max_speed <= 0.3,
             "reverse_max_speed must lie in (0, 0.3] m/s (got " +
                 std::to_string(reverse_max_speed) + ")");
  checks.positive("cusp_heading_tolerance", cusp_heading_tolerance)
      .positive("start_heading_tolerance", start_heading_tolerance)
      .positive("goal_position_tolerance", goal_position_tolerance)
      .positive("goal_heading_tolerance", goal_heading_tolerance)
      .positive("goal_timeout", goal_timeout)
      .check(max_goal_rotation_corrections >= 0, "max_goal_rotation_corrections must be >= 0")
      .positive("stale_pose_timeout", stale_pose_timeout)
      .positive("stale_odometry_timeout", stale_odometry_timeout)
      .positive("pose_jump", pose_jump)
      .positive("gap_timeout", gap_timeout)
      .check(hang_timeout >= gap_timeout, "hang_timeout must be at least gap_timeout")
      .check(max_gap_restarts >= 0, "max_gap_restarts must be >= 0")
      .positive("governor_soft_error", governor_soft_error)
      .check(governor_hard_error > governor_soft_error,
             "governor_hard_error must exceed governor_soft_error")
      .positive("governor_rate", governor_rate)
      .positive("abort_error", abort_error)
      .positive("prediction_step", prediction_step)
      .positive("kinematic_wheel_gain", kinematic_wheel_gain);
  checkLimits(checks, "stop linear", stop.linear, false);
  checkLimits(checks, "stop angular", stop.angular, false);
  return checks.result();
}

void readTrackerConfig(wheelchair_core::ConfigReader& reader, TrackerConfig& config) {
  reader.read("natural_frequency", config.natural_frequency);
  reader.read("damping", config.damping);
  reader.read("max_speed", config.path_limits.longitudinal.speed);
  reader.read("max_accel", config.path_limits.longitudinal.accel);
  reader.read("max_jerk", config.path_limits.longitudinal.jerk);
  reader.read("reverse_lookahead", config.reverse_lookahead);
  reader.read("reverse_max_speed", config.reverse_max_speed);
  reader.read("stale_pose_timeout", config.stale_pose_timeout);
  reader.read("stale_odometry_timeout", config.stale_odometry_timeout);
  reader.read("pose_jump", config.pose_jump);
  reader.read("gap_timeout", config.gap_timeout);
  reader.read("hang_timeout", config.hang_timeout);
  reader.read("max_gap_restarts", config.max_gap_restarts);
  reader.read("dynamic_terms", config.dynamic_terms);
  // A stop brakes the forward motion within the path's own comfort limits.
  config.stop.linear.accel = config.path_limits.longitudinal.accel;
  config.stop.linear.jerk = config.path_limits.longitudinal.jerk;
}

}  // namespace wheelchair_controller
