// Closed-loop simulation of PathTracker (test support of the controller's tests and benchmark,
// not part of the controller): the "real" chair is the simulator's (wheelchair_sim::Simulator:
// the paper's model, eq. 15, by RK4 at 1 kHz, rolling resistance, the parking brake; optionally
// a different mass), measured through quantized encoders and a noisy pose; the controller runs
// at 50 Hz.
#pragma once

#include <wheelchair_controller/path_tracker.h>

#include <string>
#include <vector>

namespace wheelchair_controller {

struct PlantConfig {
  ChairParams chair;             ///< the simulated chair (may differ from the controller's model)
  double physics_rate = 1000.0;  ///< [Hz] RK4
  double control_rate = 50.0;    ///< [Hz]
  bool rolling_resistance = true;
  double encoder_ticks_per_rev = 16384.0;  ///< 0: exact wheel angles
  double pose_noise_xy = 0.0;              ///< [m] std of the measured axle position
  double pose_noise_theta = 0.0;           ///< [rad]
  /// [Hz] the pose error changes at this rate and is held in between, as tf map->base_link
  /// does (localizer corrections at the scan rate, odometry-smooth in between).
  double pose_noise_rate = 5.0;
  unsigned seed = 1;
  /// From this time on [s] (negative: never) the measured pose is shifted by this offset
  /// (x, y, theta): a localization correction, as when a scan snaps map -> odom.
  double localization_correction_time = -1.0;
  Eigen::Vector3d localization_correction = Eigen::Vector3d::Zero();
  double max_time = 120.0;      ///< [s]
  double comfort_window = 0.1;  ///< [s] averaging of the measured acceleration and jerk
};

struct TraceSample {
  double t;
  Eigen::Vector2d y, y_ref;
  Eigen::Vector3d pose;  ///< true axle pose
  Eigen::Vector2d torque;
  TrackerState state;
};

struct ClosedLoopResult {
  TrackerState final_state = TrackerState::kIdle;
  std::string reason;
  double duration = 0.0;            ///< [s] until goal reached / aborted
  double mse_cm2 = 0.0;             ///< MSEre: mean |y - y_ref|^2 over active steps [cm^2]
  double max_error = 0.0;           ///< [m]
  double body_deviation_max = 0.0;  ///< axle centre P from the planned path [m]
  double body_deviation_rms = 0.0;
  double max_accel = 0.0;  ///< rider (P_c) horizontal acceleration [m/s^2]
  double max_jerk = 0.0;   ///< rider jerk [m/s^3]
  double max_accel_time = 0.0, max_jerk_time = 0.0;  ///< [s] when they occurred
  double max_speed = 0.0;                            ///< axle centre [m/s]
  double max_torque = 0.0;                           ///< [N m]
  double final_position_error = 0.0;                 ///< axle centre vs the last planned point [m]
  double final_heading_error = 0.0;                  ///< [rad]
  double convergence_distance = 0.0;  ///< [m] travelled by P until |y - y_ref| stays < 2 cm
  std::vector<double> step_seconds;   ///< wall time of each control step
  std::vector<TraceSample> trace;
};

/// The shipped chair with a heavier rider (+15 kg, body inertia +15 %) than the controller's
/// model: the plant of the tests that check the motion the controller exports.
PlantConfig heavierRiderPlant(const ChairParams& chair);

/// Runs until the tracker reaches the goal or aborts (or max_time). The chair starts at rest
/// with its axle centre at `start`.
ClosedLoopResult simulateClosedLoop(const std::vector<Pose2D>& path, const Pose2D& start,
                                    const ChairParams& model, const TrackerConfig& config,
                                    const PlantConfig& plant);

}  // namespace wheelchair_controller
