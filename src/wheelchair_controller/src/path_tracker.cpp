#include <wheelchair_controller/path_tracker.h>
#include <wheelchair_controller/start_offset.h>
#include <wheelchair_controller/torque_saturation.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace wheelchair_controller {
namespace wd = wheelchair_description;

namespace {

constexpr double kNominalStep = 0.02;   // [s] assumed control period of the first step
constexpr double kAtRestSpeed = 0.05;   // [m/s] below: may rotate in place before the path
constexpr double kSettledSpeed = 0.01;  // [m/s] rim speed below which the goal may be declared

std::string format(const char* fmt, double value) {
  char buf[128];
  std::snprintf(buf, sizeof(buf), fmt, value);
  return buf;
}

bool isActive(TrackerState s) {
  return s == TrackerState::kAligning || s == TrackerState::kTracking ||
         s == TrackerState::kReversing || s == TrackerState::kRotatingToGoal;
}

/// Internal model (section 4: the paper discretizes the dynamics with RK2): propagates x over
/// dt with torque tau in RK2 steps no longer than `step`.
wd::State predict(wd::State x, const Eigen::Vector2d& tau, double dt, double step,
                  const ChairParams& p) {
  const int n = static_cast<int>(std::ceil(std::abs(dt) / step));
  for (int i = 0; i < n; ++i) x = wd::integrateRK2(x, tau, dt / n, p);
  return x;
}

}  // namespace

const char* toString(TrackerState state) {
  switch (state) {
    case TrackerState::kIdle:
      return "idle";
    case TrackerState::kAligning:
      return "aligning";
    case TrackerState::kTracking:
      return "tracking";
    case TrackerState::kReversing:
      return "reversing";
    case TrackerState::kRotatingToGoal:
      return "rotating_to_goal";
    case TrackerState::kStopping:
      return "stopping";
    case TrackerState::kGoalReached:
      return "goal_reached";
    case TrackerState::kAborted:
      return "aborted";
  }
  return "unknown";
}

PathTracker::PathTracker(const ChairParams& chair, const TrackerConfig& config)
    : chair_(chair),
      config_(config),
      gains_(gainsFromNaturalFrequency(config.natural_frequency, config.damping)),
      stop_(chair, config.stop) {
  const std::string problem = chair_.validate();
  if (!problem.empty()) throw std::invalid_argument(problem);
}

std::shared_ptr<const OutputTrajectory> pieceTrajectory(const DrivenPiece& piece,
                                                        const ChairParams& chair,
                                                        const TrackerConfig& config,
                                                        double initial_speed) {
  if (!piece.reverse()) {
    return std::make_shared<PathOutputTrajectory>(piece.path, chair.lookahead, chair.cm_offset,
                                                  config.path_limits, config.limit_margin,
                                                  initial_speed);
  }
  // In reverse the output point P_r = P - L_r h is L_r ahead along the direction of motion t
  // (h = -t), and the rider (P_c = P - d h) is d ahead along it: the same reference with
  // lookahead L_r and the rider offset -d.
  PathLimits limits = config.path_limits;
  limits.longitudinal.speed = std::min(limits.longitudinal.speed, config.reverse_max_speed);
  return std::make_shared<PathOutputTrajectory>(piece.path, config.reverse_lookahead,
                                                -chair.cm_offset, limits, config.limit_margin,
                                                initial_speed);
}

PreparedPath preparePath(const std::vector<Pose2D>& path, const ChairParams& chair,
                         const TrackerConfig& config, double initial_speed) {
  PreparedPath out;
  out.initial_speed = initial_speed;
  std::optional<DrivenPlan> plan = drivenPlan(path, out.rejection);
  if (!plan) return out;
  try {
    for (size_t k = 0; k < plan->pieces.size(); ++k) {
      const DrivenPiece& piece = plan->pieces[k];
      // Only the first piece may start moving, and only if the chair already moves its way.
      const double along = piece.reverse() ? -initial_speed : initial_speed;
      out.trajectories.push_back(
          pieceTrajectory(piece, chair, config, k == 0 ? std::max(0.0, along) : 0.0));
    }
    out.plan = std::make_shared<const DrivenPlan>(std::move(*plan));
  } catch (const std::exception& e) {
    out.rejection = std::string("path refused: ") + e.what();
    out.trajectories.clear();
  }
  return out;
}

std::string PathTracker::setPath(const std::vector<Pose2D>& path) {
  return setPreparedPath(preparePath(path, chair_, config_, startSpeed()));
}

std::string PathTracker::setPreparedPath(const PreparedPath& prepared) {
  if (std::string refused = refuseIfHeld(); !refused.empty()) return refused;
  if (!prepared.rejection.empty() || !prepared.plan ||
      prepared.trajectories.size() != prepared.plan->pieces.size()) {
    const std::string reason =
        prepared.rejection.empty() ? "path not prepared" : prepared.rejection;
    abort(reason);
    return reason;
  }
  plan_ = prepared.plan;
  piece_trajectories_ = prepared.trajectories;
  path_pending_ = true;
  return "";
}

double PathTracker::startSpeed() const {
  if (!isActive(state_)) return 0.0;
  const double speed = wd::bodyVelocity(last_state_.tail<2>(), chair_)(0);
  return std::abs(speed) < kAtRestSpeed ? 0.0 : speed;
}

void PathTracker::abort(const std::string& reason) {
  beginStop(reason, last_state_.tail<2>(), TrackerState::kAborted);
}

void PathTracker::stepsPaused(double gap) {
  if (!isActive(state_)) return;  // at rest or stopping: nothing ran on
  const std::string paused = format("control steps paused for %.2f s", gap);
  if (gap > config_.hang_timeout) {
    abort(paused);
    return;
  }
  if (gap_restarts_ >= config_.max_gap_restarts) {
    abort(paused + format(" (%.0f restarts from rest on this path before)", gap_restarts_));
    return;
  }
  ++gap_restarts_;
  restart_reason_ = "restarting from rest: " + paused;
  restart_rest_time_ = 0.0;
  if (restarting_) return;  // a pause during the brake: the same brake goes on
  restarting_ = true;
  restart_brake_started_ = false;  // from the wheel speeds measured after the pause
  braking_for_direction_ = false;
}

bool PathTracker::restartStep(double now, double dt, const std::optional<PoseMeasurement>& pose,
                              const WheelSpeedMeasurement& wheels, TrackerOutput& out) {
  // Odometry only, as every stop: the pose may be what the pause left stale.
  const bool odometry_fresh = wheels.eta.allFinite() && std::isfinite(wheels.stamp) &&
                              now - wheels.stamp <= config_.stale_odometry_timeout;
  const Eigen::Vector2d eta =
      odometry_fresh ? wheels.eta : Eigen::Vector2d::Constant(std::nan(""));  // NaN: brake now
  have_last_ = true;
  last_time_ = now;
  if (odometry_fresh) last_state_.tail<2>() = wheels.eta;
  if (odometry_fresh && pose && pose->pose.isFinite() &&
      now - pose->stamp <= config_.stale_pose_timeout)
    last_state_ = estimateState(now, *pose, wheels.eta);  // the pose-jump check's base
  last_torque_.setZero();
  last_body_accel_.setZero();
  out.state = state_;
  out.reason = restart_reason_;
  if (!restart_brake_started_) {
    // From the wheel speeds as they are after the pause (the motors braked on their watchdog
    // meanwhile, the last commanded acceleration is past): none measured, the brake at once.
    stop_.start(eta, 0.0, 0.0);
    restart_brake_started_ = true;
  }
  if (!stop_.finished()) {
    out.command = stop_.step(eta, dt);
    out.command.torque = saturateTorque(out.command.torque, chair_.max_wheel_torque).torque;
    if (!out.command.brake) {
      last_torque_ = out.command.torque;
      return true;
    }
  }
  out.command = WheelCommand{};  // the brake, until the drive goes on
  const double rim_speed =
      odometry_fresh ? wheels.eta.cwiseAbs().maxCoeff() * chair_.wheel_radius : INFINITY;
  const std::string fault = checkInputs(now, pose, wheels);
  if (rim_speed < kSettledSpeed && fault.empty()) {
    restarting_ = false;
    return false;
  }
  restart_rest_time_ += dt;
  if (restart_rest_time_ > config_.hang_timeout) {
    restarting_ = false;
    beginStop(restart_reason_ + ", then " +
                  (fault.empty() ? format("not at rest (rim speed %.3f m/s)", rim_speed) : fault),
              odometry_fresh ? wheels.eta : Eigen::Vector2d::Zero(), TrackerState::kAborted);
    out = stopStep(dt, odometry_fresh ? wheels.eta : Eigen::Vector2d::Zero());
  }
  return true;
}

void PathTracker::retimeFromRest(const State& x, bool from_start) {
  Phase& phase = phases_.front();
  const Eigen::Vector2d y = outputPoint(x.head<5>(), chair_, phase.ell);
  // The chair braked to rest either behind the reference (it stood during the brake) or ahead
  // of it (the brake's distance): searched a few seconds of reference time either way.
  const double t0 =
      from_start ? 0.0 : nearestTime(*phase.trajectory, y, phase_time_ - 3.0, phase_time_ + 6.0);
  const double speed = phase.trajectory->at(t0).velocity.norm();
  phase.trajectory = std::make_shared<RestartFromRestTrajectory>(
      phase.trajectory, t0, restartRampTime(speed, config_.path_limits.longitudinal));
  phase_time_ = 0.0;
  overtime_ = 0.0;
  rate_dot_ = 0.0;
  rate_initialized_ = false;
  startFromHere(x);
}

void PathTracker::hold(const std::string& source, const std::string& reason) {
  holds_[source] = reason;
  abort(reason);
}

void PathTracker::release(const std::string& source) { holds_.erase(source); }

std::string PathTracker::holdReason() const { return holds_.empty() ? "" : holds_.begin()->second; }

std::string PathTracker::refuseIfHeld() {
  const std::string held = holdReason();
  if (held.empty()) return "";
  const std::string refused = "path ignored during " + held;
  abort(refused);  // at rest: a stop from standstill, only to put the refusal on the status
  return refused;
}

void PathTracker::beginStop(const std::string& reason, const Eigen::Vector2d& eta,
                            TrackerState end_state) {
  phases_.clear();
  path_pending_ = false;
  braking_for_direction_ = false;
  restarting_ = false;
  restart_new_path_ = false;
  // Reaching the goal ends this path, it is no stop a newer path must respect: a path that
  // came during the final moments (the rider's next goal) is still driven.
  if (end_state != TrackerState::kGoalReached) ++stop_count_;
  if (state_ == TrackerState::kStopping) return;  // keep the first reason
  reason_ = reason;
  stop_end_state_ = end_state;
  state_ = TrackerState::kStopping;
  stop_.start(eta, last_body_accel_(0), last_body_accel_(1));
}

TrackerOutput PathTracker::stopStep(double dt, const Eigen::Vector2d& eta) {
  TrackerOutput out;
  out.command = stop_.step(eta, dt);
  out.command.torque = saturateTorque(out.command.torque, chair_.max_wheel_torque).torque;
  if (stop_.finished()) state_ = stop_end_state_;
  last_body_accel_.setZero();
  out.state = state_;
  out.reason = reason_;
  return out;
}

std::string PathTracker::checkInputs(double now, const std::optional<PoseMeasurement>& pose,
                                     const WheelSpeedMeasurement& wheels) const {
  if (!std::isfinite(now)) return "non-finite time";
  if (!wheels.eta.allFinite() || !std::isfinite(wheels.stamp)) return "non-finite wheel speeds";
  if (now - wheels.stamp > config_.stale_odometry_timeout)
    return format("stale odometry (%.3f s old)", now - wheels.stamp);
  if (!pose) return "no pose (localization lost)";
  if (!pose->pose.isFinite() || !std::isfinite(pose->stamp)) return "non-finite pose";
  if (now - pose->stamp > config_.stale_pose_timeout)
    return format("stale pose (%.3f s old)", now - pose->stamp);
  if (have_last_ && isActive(state_)) {
    const wd::State expected = predict(last_state_, last_torque_, pose->stamp - last_time_,
                                       config_.prediction_step, chair_);
    const double jump = (wd::axlePose(expected, chair_).head<2>() - pose->pose.position()).norm();
    if (jump > config_.pose_jump) return format("pose jump of %.2f m", jump);
  }
  return "";
}

wd::State PathTracker::estimateState(double now, const PoseMeasurement& pose,
                                     const Eigen::Vector2d& eta) const {
  wd::State x;
  x.head<5>() = configurationAtAxlePose(pose.pose, chair_);
  x.tail<2>() = eta;
  const double latency = now - pose.stamp;
  return latency > 0.0 ? predict(x, last_torque_, latency, config_.prediction_step, chair_) : x;
}

void PathTracker::startPhases(const State& x) {
  phases_.clear();
  const Eigen::Vector3d p = wd::axlePose(x, chair_);
  const double speed = wd::bodyVelocity(x.tail<2>(), chair_)(0);
  const double l = chair_.lookahead;
  const bool at_rest = std::abs(speed) < kAtRestSpeed;
  const auto rotation = [&](const Eigen::Vector2d& centre, double from, double to) {
    return Phase{
        std::make_shared<RotationOutputTrajectory>(centre, from, to, l, config_.rotation_limits),
        TrackerState::kAligning, l, false};
  };
  const std::vector<DrivenPiece>& pieces = plan_->pieces;
  for (size_t k = 0; k < pieces.size(); ++k) {
    const DrivenPiece& piece = pieces[k];
    if (k == 0 && at_rest && rotatesBeforePiece(piece, p.z(), config_))
      phases_.push_back(rotation(p.head<2>(), p.z(), piece.startHeading()));
    // At a cusp the chair has stopped with the last piece's end heading.
    if (k > 0 && rotatesBeforePiece(piece, pieces[k - 1].endHeading(), config_, true))
      phases_.push_back(
          rotation(piece.path->at(0.0).position, pieces[k - 1].endHeading(), piece.startHeading()));
    phases_.push_back({piece_trajectories_[k],
                       piece.reverse() ? TrackerState::kReversing : TrackerState::kTracking,
                       piece.reverse() ? -config_.reverse_lookahead : l, k + 1 < pieces.size()});
  }
  const DrivenPiece& last = pieces.back();
  goal_heading_ = plan_->goal_heading;
  if (rotatesToGoalHeading(*plan_, config_)) {
    Phase goal =
        rotation(last.path->at(last.path->length()).position, last.endHeading(), goal_heading_);
    goal.state = TrackerState::kRotatingToGoal;
    phases_.push_back(goal);
  } else {
    goal_heading_ = last.endHeading();
  }
  state_ = phases_.front().state;
  reason_.clear();
  gap_restarts_ = 0;
  phase_time_ = 0.0;
  overtime_ = 0.0;
  goal_rotation_corrections_ = 0;
  rate_dot_ = 0.0;
  rate_initialized_ = false;
}

OutputReference PathTracker::governedReference(double dt, double error) {
  // Anti-windup: the reference is open-loop in time, so when the chair falls behind (torque
  // saturation, an obstacle to the wheels, a large initial offset) its time rate is lowered
  // rather than letting the error and the commanded torque grow.
  const double span = config_.governor_hard_error - config_.governor_soft_error;
  double target = std::clamp((config_.governor_hard_error - error) / span, 0.0, 1.0);
  target = std::min(target, last_saturation_ < 1.0 ? last_saturation_ : 1.0);
  if (std::isfinite(speed_limit_)) {  // the supervisor's speed limit caps the time rate
    const double speed = phases_.front().trajectory->at(phase_time_).velocity.norm();
    if (speed > 1e-3) target = std::min(target, std::max(0.0, speed_limit_) / speed);
  }
  if (!rate_initialized_) {
    rate_ = target;
    rate_initialized_ = true;
  }
  rate_dot_ = std::clamp((target - rate_) / dt, -config_.governor_rate, config_.governor_rate);
  rate_ += rate_dot_ * dt;
  phase_time_ += rate_ * dt;
  return scaledReference();
}

OutputReference PathTracker::scaledReference() const {
  const OutputReference r = phases_.front().trajectory->at(phase_time_);
  OutputReference out = r;
  out.velocity = rate_ * r.velocity;
  out.acceleration = rate_ * rate_ * r.acceleration + rate_dot_ * r.velocity;
  return out;
}

void PathTracker::startFromHere(const State& x) {
  Phase& phase = phases_.front();
  phase.trajectory = startingFrom(phase.trajectory, outputPoint(x.head<5>(), chair_, phase.ell),
                                  config_.start_offset_limits);
}

bool PathTracker::advancePhase(double dt, const State& x, double error) {
  if (phase_time_ < phases_.front().trajectory->duration()) return true;
  const double rim_speed = x.tail<2>().cwiseAbs().maxCoeff() * chair_.wheel_radius;
  if (phases_.size() > 1) {
    // A cusp: the reference has come to rest; the chair must too before it changes direction.
    if (phases_.front().rest_before_next && rim_speed >= kSettledSpeed) {
      overtime_ += dt;
      if (overtime_ <= config_.goal_timeout) return true;
      beginStop(format("did not come to rest at a cusp (rim speed %.3f m/s)", rim_speed),
                x.tail<2>(), TrackerState::kAborted);
      return false;
    }
    overtime_ = 0.0;
    phases_.erase(phases_.begin());
    state_ = phases_.front().state;
    phase_time_ = 0.0;
    startFromHere(x);
    return true;
  }
  const double heading_error = std::remainder(x(wd::kTheta) - goal_heading_, 2.0 * M_PI);
  if (error < config_.goal_position_tolerance &&
      std::abs(heading_error) < config_.goal_heading_tolerance && rim_speed < kSettledSpeed) {
    beginStop("", x.tail<2>(), TrackerState::kGoalReached);
    return false;
  }
  if (error < config_.goal_position_tolerance && rim_speed < kSettledSpeed &&
      goal_rotation_corrections_ < config_.max_goal_rotation_corrections) {
    // Settled, P_l in place, heading off: a bounded in-place rotation about the axle as it is.
    ++goal_rotation_corrections_;
    const Eigen::Vector3d p = wd::axlePose(x, chair_);
    phases_.front() = {
        std::make_shared<RotationOutputTrajectory>(p.head<2>(), p.z(), goal_heading_,
                                                   chair_.lookahead, config_.rotation_limits),
        TrackerState::kRotatingToGoal, chair_.lookahead, false};
    state_ = TrackerState::kRotatingToGoal;
    phase_time_ = 0.0;
    overtime_ = 0.0;
    return true;
  }
  overtime_ += dt;
  if (overtime_ > config_.goal_timeout) {
    beginStop(format("goal not reached within tolerance (P_l %.3f m off)", error), x.tail<2>(),
              TrackerState::kAborted);
    return false;
  }
  return true;
}

Eigen::Vector2d PathTracker::trackingTorque(const State& x, const OutputReference& ref) const {
  const Vector5 q = x.head<5>();
  const Eigen::Vector2d eta = x.tail<2>();
  const double ell = phases_.front().ell;
  const Eigen::Vector2d y = outputPoint(q, chair_, ell);
  if (!config_.dynamic_terms) {  // kinematic baseline: wheel speeds from y_dot = Phi eta
    const Eigen::Vector2d y_dot_cmd = ref.velocity + config_.natural_frequency * (ref.position - y);
    const Eigen::Vector2d eta_cmd =
        decouplingMatrix(q, chair_, ell).partialPivLu().solve(y_dot_cmd);
    return config_.kinematic_wheel_gain * (eta_cmd - eta);
  }
  const Eigen::Vector2d v =
      outerLaw(ref, y, outputVelocity(q, eta, chair_, ell), gains_, config_.max_feedback_accel);
  const Eigen::Vector2d u = linearizingInput(q, eta, v, chair_, ell);
  Eigen::Vector2d tau = computedTorque(q, eta, u, chair_);
  if (config_.compensate_rolling_resistance) tau += rollingResistanceTorque(eta, chair_);
  return tau;
}

bool PathTracker::brakeForDirection(double now, double dt, const State& x, TrackerOutput& out) {
  const double speed = wd::bodyVelocity(x.tail<2>(), chair_)(0);
  const bool against =
      std::abs(speed) >= kAtRestSpeed && (speed < 0.0) != plan_->pieces.front().reverse();
  if (!against && !braking_for_direction_) return false;
  if (!braking_for_direction_) {
    braking_for_direction_ = true;
    stop_.start(x.tail<2>(), last_body_accel_(0), last_body_accel_(1));
  }
  out.command = stop_.step(x.tail<2>(), dt);
  out.command.torque = saturateTorque(out.command.torque, chair_.max_wheel_torque).torque;
  out.command.brake = false;  // the path starts from rest right after
  out.state = state_;
  have_last_ = true;
  last_time_ = now;
  last_state_ = x;
  last_torque_ = out.command.torque;
  last_body_accel_.setZero();
  if (!stop_.finished()) return true;
  braking_for_direction_ = false;
  return false;
}

TrackerOutput PathTracker::update(double now, const std::optional<PoseMeasurement>& pose,
                                  const WheelSpeedMeasurement& wheels) {
  if (have_last_ && now - last_time_ > config_.gap_timeout) stepsPaused(now - last_time_);
  const double dt =
      have_last_ ? std::clamp(now - last_time_, 1e-4, 10.0 * kNominalStep) : kNominalStep;
  TrackerOutput out;
  bool restarted = false;
  if (restarting_) {
    if (restartStep(now, dt, pose, wheels, out)) return out;
    restarted = true;
    // a path that came during the brake starts from rest (it was prepared while moving)
    if (path_pending_) restart_new_path_ = true;
  }
  const bool resume = path_pending_;
  if (!isActive(state_) && !resume) {
    if (state_ == TrackerState::kStopping) out = stopStep(dt, wheels.eta);
    out.state = state_;
    out.reason = reason_;
    have_last_ = true;
    last_time_ = now;
    last_state_.tail<2>() = wheels.eta.allFinite() ? wheels.eta : Eigen::Vector2d::Zero();
    return out;
  }
  const std::string fault = checkInputs(now, pose, wheels);
  if (!fault.empty()) {
    const Eigen::Vector2d eta = wheels.eta.allFinite() ? wheels.eta : Eigen::Vector2d::Zero();
    beginStop(fault, eta, TrackerState::kAborted);
    have_last_ = false;
    last_time_ = now;
    return stopStep(dt, eta);
  }
  const State x = estimateState(now, *pose, wheels.eta);
  if (resume) {
    if (brakeForDirection(now, dt, x, out)) return out;
    if (state_ == TrackerState::kStopping) state_ = TrackerState::kIdle;
    startPhases(x);
    if (restart_new_path_)
      retimeFromRest(x, true);
    else
      startFromHere(x);
    restart_new_path_ = false;
    path_pending_ = false;
  } else if (restarted) {
    retimeFromRest(x, false);
  }
  const Vector5 q = x.head<5>();
  out.output_offset = phases_.front().ell;
  out.y = outputPoint(q, chair_, out.output_offset);
  const double error_before = (phases_.front().trajectory->at(phase_time_).position - out.y).norm();
  out.reference = governedReference(dt, error_before);
  const double error = (out.reference.position - out.y).norm();
  if (error > config_.abort_error) {
    beginStop(format("tracking error %.2f m", error), x.tail<2>(), TrackerState::kAborted);
    return stopStep(dt, x.tail<2>());
  }
  const std::shared_ptr<const OutputTrajectory> phase_before = phases_.front().trajectory;
  if (!advancePhase(dt, x, error)) return stopStep(dt, x.tail<2>());
  if (phases_.front().trajectory != phase_before) {
    // A new phase (perhaps with the output point on the other side of the axle, at a cusp):
    // its own output and reference from this step on.
    out.output_offset = phases_.front().ell;
    out.y = outputPoint(q, chair_, out.output_offset);
    out.reference = scaledReference();
  }

  const SaturatedTorque sat =
      saturateTorque(trackingTorque(x, out.reference), chair_.max_wheel_torque);
  last_saturation_ = sat.scale;
  // Commanded body acceleration (a, w_dot), the start of a controlled stop if one follows.
  const Eigen::Vector2d eta_dot = wd::wheelAcceleration(q, x.tail<2>(), sat.torque, chair_);
  last_body_accel_ = wd::bodyVelocity(eta_dot, chair_);
  have_last_ = true;
  last_time_ = now;
  last_state_ = x;
  last_torque_ = sat.torque;

  out.command.torque = sat.torque;
  out.command.brake = false;
  out.state = state_;
  out.has_reference = true;
  out.body_deviation = plan_->distanceToPlanned(wd::axlePose(x, chair_).head<2>());
  out.saturation_scale = sat.scale;
  out.reference_rate = rate_;
  return out;
}

}  // namespace wheelchair_controller
