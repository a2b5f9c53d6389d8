// The controller: path in, wheel torques out. Phases: optional in-place alignment to the path,
// then per piece of the path (split at its cusps, driven_motion.h) tracking of an output point
// on the side the chair moves towards (P_l = P + L h forwards, P_r = P - L_r h in reverse,
// off-tracking compensated), a stop at each cusp (and an in-place rotation there if the headings
// differ), in-place rotation to the goal heading, brake. Every fault (non-finite or stale input,
// pose jump, empty or zero-length path, tracking error too large) ends in the same
// ControlledStop.
#pragma once

#include <wheelchair_controller/controlled_stop.h>
#include <wheelchair_controller/driven_motion.h>
#include <wheelchair_controller/linearization.h>
#include <wheelchair_controller/output_trajectory.h>
#include <wheelchair_controller/tracker_config.h>
#include <wheelchair_core/pose2d.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wheelchair_controller {

enum class TrackerState {
  kIdle,
  kAligning,
  kTracking,
  kReversing,  ///< tracking a piece of the path driven in reverse
  kRotatingToGoal,
  kStopping,
  kGoalReached,
  kAborted
};
const char* toString(TrackerState state);

struct PoseMeasurement {
  double stamp = 0.0;  ///< [s]
  Pose2D pose;         ///< base_link (axle centre P) in map
};
struct WheelSpeedMeasurement {
  double stamp = 0.0;
  Eigen::Vector2d eta = Eigen::Vector2d::Zero();  ///< [psi_r_dot, psi_l_dot] rad/s
};

/// What one control step produced, for the actuators and for monitoring.
struct TrackerOutput {
  WheelCommand command;
  TrackerState state = TrackerState::kIdle;
  std::string reason;                           ///< why the last stop began (empty otherwise)
  bool has_reference = false;                   ///< y, reference, body_deviation valid
  Eigen::Vector2d y = Eigen::Vector2d::Zero();  ///< the output point (estimated)
  /// Signed offset ell of the output point ahead of the axle: L (P_l) forwards and in
  /// rotations, -L_r (P_r, behind the axle) in reverse.
  double output_offset = 0.0;
  OutputReference reference;
  double body_deviation = 0.0;  ///< distance of the axle centre P from the planned path [m]
  double saturation_scale = 1.0;
  double reference_rate = 1.0;  ///< governor's time rate (1: on schedule)
};

/// A path made ready for tracking: its pieces smoothed (driven_motion.h) and a time-parametrized
/// reference per piece. Building it is the expensive part (up to ~1 s of CPU on a long curvy
/// path), so the nodelet does it off the control thread and swaps the result in
/// (PathTracker::setPreparedPath).
struct PreparedPath {
  std::string rejection;  ///< non-empty: the path is refused, and why
  std::shared_ptr<const DrivenPlan> plan;
  std::vector<std::shared_ptr<const OutputTrajectory>> trajectories;  ///< one per piece
  double initial_speed = 0.0;  ///< [m/s] signed body speed when the path was requested
};
/// Smooths the path's pieces and builds their references; the first piece's starts at the
/// chair's speed `initial_speed` (m/s, signed: negative backwards) if the chair moves its way,
/// else at rest (the tracker then brakes first).
PreparedPath preparePath(const std::vector<Pose2D>& path, const ChairParams& chair,
                         const TrackerConfig& config, double initial_speed);
/// The reference of one piece: forwards the paper's P_l (L ahead, comfort limits of the
/// config), in reverse P_r (reverse_lookahead behind the axle, speed at most reverse_max_speed).
std::shared_ptr<const OutputTrajectory> pieceTrajectory(const DrivenPiece& piece,
                                                        const ChairParams& chair,
                                                        const TrackerConfig& config,
                                                        double initial_speed);

class PathTracker {
 public:
  PathTracker(const ChairParams& chair, const TrackerConfig& config);

  /// New path (base_link poses in map), replacing the current one. A rejected path
  /// (empty, non-finite, zero-length) starts a controlled stop; the reason is returned.
  std::string setPath(const std::vector<Pose2D>& path);
  /// As setPath with a path prepared elsewhere (preparePath). Refused while a hold is active.
  std::string setPreparedPath(const PreparedPath& prepared);
  /// Body speed [m/s] (signed: negative backwards) a path given now should start with (0 when
  /// not moving along a path).
  double startSpeed() const;
  /// Stops (controlled) with the given reason.
  void abort(const std::string& reason);
  /// The control steps paused for `gap` seconds (update() calls it itself for a gap of its
  /// `now` beyond config.gap_timeout; the nodelet for one of wall time). While driving: up to
  /// config.hang_timeout, and at most config.max_gap_restarts times a path, the chair brakes to
  /// rest (odometry only), then the current phase's reference is re-timed from rest at the point
  /// nearest the chair (RestartFromRestTrajectory) and the drive goes on; a longer pause, or
  /// one more, is a hang: a controlled stop. Elsewhere (idle, stopping) nothing ran on.
  void stepsPaused(double gap);
  /// A stop that lasts: e.g. the safety supervisor's stop or a lost localization. Stops now
  /// (controlled) and refuses paths until every hold is released; then a new path resumes.
  void hold(const std::string& source, const std::string& reason);
  void release(const std::string& source);
  /// The safety supervisor's protective field: drive no faster than `speed` [m/s] (+inf: no
  /// limit). The governor slows the reference's time rate to it (within governor_rate).
  void setSpeedLimit(double speed) { speed_limit_ = std::isnan(speed) ? 0.0 : speed; }
  /// Reason of the first active hold (empty: none).
  std::string holdReason() const;
  /// While a hold is active a new path is refused where the rider sees it: the status says
  /// "path ignored during <hold>" (a stop already running keeps its first reason). Returns
  /// that refusal, or empty when no hold is active.
  std::string refuseIfHeld();
  /// Counts the stops begun (not the goal's own braking): a path prepared before a stop must
  /// not undo it.
  uint64_t stopCount() const { return stop_count_; }
  /// One control step at time `now` [s]: latest pose (nullopt: none, e.g. lost
  /// localization) and wheel speeds from odometry.
  TrackerOutput update(double now, const std::optional<PoseMeasurement>& pose,
                       const WheelSpeedMeasurement& wheels);

  TrackerState state() const { return state_; }
  const std::string& reason() const { return reason_; }
  const TrackerConfig& config() const { return config_; }

 private:
  using State = wheelchair_description::State;
  std::string checkInputs(double now, const std::optional<PoseMeasurement>& pose,
                          const WheelSpeedMeasurement& wheels) const;
  State estimateState(double now, const PoseMeasurement& pose, const Eigen::Vector2d& eta) const;
  void startPhases(const State& x);
  /// The current phase's reference made to start at the chair's P_l (start_offset.h).
  void startFromHere(const State& x);
  /// Advances the reference time (governor: anti-windup) and returns the reference.
  OutputReference governedReference(double dt, double error);
  /// The current phase's reference at the reference time, scaled by the governor's rate.
  OutputReference scaledReference() const;
  /// At the end of a phase: next phase (after coming to rest at a cusp), goal reached, or goal
  /// timeout. False: stop began.
  bool advancePhase(double dt, const State& x, double error);
  /// A new path whose first piece goes against the chair's motion: brake to rest first. True
  /// while braking (`out` filled).
  bool brakeForDirection(double now, double dt, const State& x, TrackerOutput& out);
  /// One step of the brake after a pause (stepsPaused); at rest with fresh inputs it re-times
  /// the drive from rest and returns false (the step goes on as a drive step), else true with
  /// `out` filled.
  bool restartStep(double now, double dt, const std::optional<PoseMeasurement>& pose,
                   const WheelSpeedMeasurement& wheels, TrackerOutput& out);
  /// The current phase (or, `from_start`, a phase just begun) re-timed from rest at the point
  /// of its reference nearest the chair.
  void retimeFromRest(const State& x, bool from_start);
  Eigen::Vector2d trackingTorque(const State& x, const OutputReference& ref) const;
  void beginStop(const std::string& reason, const Eigen::Vector2d& eta, TrackerState end_state);
  TrackerOutput stopStep(double dt, const Eigen::Vector2d& eta);

  ChairParams chair_;
  TrackerConfig config_;
  OuterGains gains_;
  ControlledStop stop_;
  TrackerState state_ = TrackerState::kIdle, stop_end_state_ = TrackerState::kAborted;
  std::string reason_;

  std::shared_ptr<const DrivenPlan> plan_;
  std::vector<std::shared_ptr<const OutputTrajectory>> piece_trajectories_;
  bool path_pending_ = false;
  bool braking_for_direction_ = false;
  bool restarting_ = false;  ///< braking after a pause (stepsPaused)
  bool restart_brake_started_ = false;
  std::string restart_reason_;      ///< "restarting from rest: control steps paused for ..."
  double restart_rest_time_ = 0.0;  ///< [s] since the brake ended, waiting for fresh inputs
  int gap_restarts_ = 0;            ///< on this path
  bool restart_new_path_ = false;   ///< a path came during the brake: it starts from rest
  std::map<std::string, std::string> holds_;  ///< source -> reason
  uint64_t stop_count_ = 0;
  struct Phase {
    std::shared_ptr<const OutputTrajectory> trajectory;
    TrackerState state;
    double ell;             ///< signed offset of the output point ahead of the axle
    bool rest_before_next;  ///< a cusp follows: come to rest before the next phase
  };
  std::vector<Phase> phases_;  ///< remaining phases, current first
  double goal_heading_ = 0.0;
  double phase_time_ = 0.0, rate_ = 1.0, rate_dot_ = 0.0, overtime_ = 0.0;
  int goal_rotation_corrections_ = 0;
  bool rate_initialized_ = false;
  double speed_limit_ = INFINITY;  ///< [m/s] from the supervisor's field
  double last_saturation_ = 1.0;
  Eigen::Vector2d last_body_accel_ = Eigen::Vector2d::Zero();  ///< (a, w_dot) commanded

  bool have_last_ = false;
  double last_time_ = 0.0;
  State last_state_ = State::Zero();
  Eigen::Vector2d last_torque_ = Eigen::Vector2d::Zero();
};

}  // namespace wheelchair_controller
