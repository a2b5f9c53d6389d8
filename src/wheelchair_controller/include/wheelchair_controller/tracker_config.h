// The path tracker's configuration: defaults in the declaration, validate() says what is wrong,
// readTrackerConfig() names every key (the nodelet's private parameters, or a YAML file for an
// offline tool: wheelchair_core/config.h).
#pragma once

#include <wheelchair_controller/controlled_stop.h>
#include <wheelchair_controller/motion_profile.h>
#include <wheelchair_controller/output_trajectory.h>
#include <wheelchair_core/config.h>

#include <string>

namespace wheelchair_controller {

struct TrackerConfig {
  double natural_frequency = 2.5;   ///< w_n of the output error dynamics [rad/s]
  double damping = 1.0;             ///< zeta (1: critically damped, no overshoot)
  double max_feedback_accel = 0.5;  ///< |feedback part of v| limit [m/s^2]
  PathLimits path_limits;           ///< comfort limits (speed 0.8, accel 0.5, jerk 1.0)
  double limit_margin = 0.7;        ///< the nominal reference uses this share of the comfort limits
  MotionLimits rotation_limits{0.6, 0.8, 1.6};  ///< in-place rotation [rad/s, rad/s^2, rad/s^3]
  /// A phase starting with P_l off its reference: the offset decays within these (accel,
  /// jerk) limits of its own (start_offset.h); the rider sees them amplified by the turning.
  MotionLimits start_offset_limits{0.0, 0.1, 0.2};
  /// Reverse pieces: the output point P_r lies this far behind the axle (README, "Reverse": the
  /// zero dynamics are stable only with the point on the side the chair moves towards).
  double reverse_lookahead = 0.15;  ///< L_r [m]
  double reverse_max_speed = 0.3;   ///< [m/s] speed limit in reverse (at most 0.3)
  /// [rad] at a cusp (at rest) a larger difference between the heading the chair stops with and
  /// the next piece's start heading is turned in place (each piece is smoothed on its own, so
  /// their end tangents differ by a few degrees); driving off with it costs lateral jerk.
  double cusp_heading_tolerance = 0.02;
  double start_heading_tolerance = 0.5;   ///< [rad] larger: rotate in place before the path
  double goal_position_tolerance = 0.05;  ///< [m] P_l at the end of the reference
  double goal_heading_tolerance = 0.05;   ///< [rad]
  double goal_timeout = 5.0;  ///< [s] after the reference ends, to settle within tolerance
  /// Settled at the goal with P_l in tolerance but the heading not: rotate again about the
  /// axle where it now is, at most this many times. Only P_l is controlled, so a localization
  /// correction of a few cm during the final rotation turns into l-scaled heading error.
  int max_goal_rotation_corrections = 2;
  double stale_pose_timeout = 0.2;  ///< [s]
  /// [s] a control step this much later than the previous one while driving is a pause (the
  /// process was stopped or starved; the motors braked on their watchdog while the reference
  /// would have run on): the chair brakes to rest, the reference is re-timed from rest where
  /// the chair stands, and the drive goes on (PathTracker::stepsPaused).
  double gap_timeout = 0.1;
  /// [s] a longer pause is a hang: the drive ends in a controlled stop (the rider's next
  /// command starts it again); so does a pause after max_gap_restarts restarts on one path.
  double hang_timeout = 1.0;
  int max_gap_restarts = 5;
  double stale_odometry_timeout = 0.2;  ///< [s]
  double pose_jump = 0.5;             ///< [m] between the predicted and the measured axle position
  double governor_soft_error = 0.10;  ///< [m] reference slows above this tracking error
  double governor_hard_error = 0.40;  ///< [m] reference waits above this tracking error
  double governor_rate = 1.0;         ///< [1/s] max change of the reference's time rate
  double abort_error = 1.0;           ///< [m] tracking error that aborts
  double prediction_step = 0.02;      ///< [s] RK2 step of the internal model
  bool dynamic_terms = true;  ///< false: kinematic baseline (no f1, f2, no rolling feed-forward)
  double kinematic_wheel_gain = 20.0;  ///< [N m s/rad] baseline's wheel-speed loop
  bool compensate_rolling_resistance = true;
  StopConfig stop;

  /// Empty if usable, else every problem (wheelchair_core::ConfigChecks).
  std::string validate() const;
};

/// Keys: natural_frequency, damping, max_speed, max_accel, max_jerk (the path's comfort
/// limits; the controlled stop brakes within the same linear accel and jerk),
/// reverse_lookahead, reverse_max_speed, stale_pose_timeout, stale_odometry_timeout, pose_jump,
/// gap_timeout, hang_timeout, max_gap_restarts, dynamic_terms.
void readTrackerConfig(wheelchair_core::ConfigReader& reader, TrackerConfig& config);

}  // namespace wheelchair_controller
