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
         s == TrackerState::kRotatingToGoal;
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

PreparedPath preparePath(const std::vector<Pose2D>& path, const ChairParams& chair,
                         const TrackerConfig& config, double initial_speed) {
  PreparedPath out;
  out.initial_speed = initial_speed;
  std::shared_ptr<const SmoothPath> smooth = drivenPath(path, out.rejection);
  if (!smooth) return out;
  try {
    out.trajectory = std::make_shared<PathOutputTrajectory>(smooth, chair.lookahead,
                                                            chair.cm_offset, config.path_limits,
                                                            config.limit_margin, initial_speed);
    out.path = smooth;
  } catch (const std::exception& e) {
    out.rejection = std::string("path refused: ") + e.what();
  }
  return out;
}

std::string PathTracker::setPath(const std::vector<Pose2D>& path) {
  return setPreparedPath(preparePath(path, chair_, config_, startSpeed()));
}

std::string PathTracker::setPreparedPath(const PreparedPath& prepared) {
  if (std::string refused = refuseIfHeld(); !refused.empty()) return refused;
  if (!prepared.rejection.empty() || !prepared.path || !prepared.trajectory) {
    const std::string reason =
        prepared.rejection.empty() ? "path not prepared" : prepared.rejection;
    abort(reason);
    return reason;
  }
  path_ = prepared.path;
  path_trajectory_ = prepared.trajectory;
  path_pending_ = true;
  return "";
}

double PathTracker::startSpeed() const {
  if (!isActive(state_)) return 0.0;
  const double speed = wd::bodyVelocity(last_state_.tail<2>(), chair_)(0);
  return std::abs(speed) < kAtRestSpeed ? 0.0 : std::max(0.0, speed);
}

void PathTracker::abort(const std::string& reason) {
  beginStop(reason, last_state_.tail<2>(), TrackerState::kAborted);
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
  const PathPoint start = path_->at(0.0), end = path_->at(path_->length());
  const bool at_rest = std::abs(speed) < kAtRestSpeed;
  if (at_rest && rotatesBeforePath(*path_, p.z(), config_)) {
    phases_.push_back({std::make_shared<RotationOutputTrajectory>(p.head<2>(), p.z(), start.heading,
                                                                  l, config_.rotation_limits),
                       TrackerState::kAligning});
  }
  phases_.push_back({path_trajectory_, TrackerState::kTracking});
  goal_heading_ = path_->goalHeading();
  if (rotatesToGoalHeading(*path_, config_)) {
    phases_.push_back({std::make_shared<RotationOutputTrajectory>(
                           end.position, end.heading, goal_heading_, l, config_.rotation_limits),
                       TrackerState::kRotatingToGoal});
  } else {
    goal_heading_ = end.heading;
  }
  state_ = phases_.front().state;
  reason_.clear();
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
  const OutputReference r = phases_.front().trajectory->at(phase_time_);
  OutputReference out = r;
  out.velocity = rate_ * r.velocity;
  out.acceleration = rate_ * rate_ * r.acceleration + rate_dot_ * r.velocity;
  return out;
}

void PathTracker::startFromHere(const State& x) {
  Phase& phase = phases_.front();
  phase.trajectory =
      startingFrom(phase.trajectory, outputPoint(x.head<5>(), chair_), config_.start_offset_limits);
}

bool PathTracker::advancePhase(double dt, const State& x, double error) {
  if (phase_time_ < phases_.front().trajectory->duration()) return true;
  if (phases_.size() > 1) {
    phases_.erase(phases_.begin());
    state_ = phases_.front().state;
    phase_time_ = 0.0;
    startFromHere(x);
    return true;
  }
  const double heading_error = std::remainder(x(wd::kTheta) - goal_heading_, 2.0 * M_PI);
  const double rim_speed = x.tail<2>().cwiseAbs().maxCoeff() * chair_.wheel_radius;
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
        TrackerState::kRotatingToGoal};
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
  const Eigen::Vector2d y = outputPoint(q, chair_);
  if (!config_.dynamic_terms) {  // kinematic baseline: wheel speeds from y_dot = Phi eta
    const Eigen::Vector2d y_dot_cmd = ref.velocity + config_.natural_frequency * (ref.position - y);
    const Eigen::Vector2d eta_cmd = decouplingMatrix(q, chair_).partialPivLu().solve(y_dot_cmd);
    return config_.kinematic_wheel_gain * (eta_cmd - eta);
  }
  const Eigen::Vector2d v =
      outerLaw(ref, y, outputVelocity(q, eta, chair_), gains_, config_.max_feedback_accel);
  const Eigen::Vector2d u = linearizingInput(q, eta, v, chair_);
  Eigen::Vector2d tau = computedTorque(q, eta, u, chair_);
  if (config_.compensate_rolling_resistance) tau += rollingResistanceTorque(eta, chair_);
  return tau;
}

TrackerOutput PathTracker::update(double now, const std::optional<PoseMeasurement>& pose,
                                  const WheelSpeedMeasurement& wheels) {
  const double dt =
      have_last_ ? std::clamp(now - last_time_, 1e-4, 10.0 * kNominalStep) : kNominalStep;
  const bool resume = path_pending_;
  TrackerOutput out;
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
    if (state_ == TrackerState::kStopping) state_ = TrackerState::kIdle;
    startPhases(x);
    startFromHere(x);
    path_pending_ = false;
  }
  const Vector5 q = x.head<5>();
  out.y = outputPoint(q, chair_);
  const double error_before = (phases_.front().trajectory->at(phase_time_).position - out.y).norm();
  out.reference = governedReference(dt, error_before);
  const double error = (out.reference.position - out.y).norm();
  if (error > config_.abort_error) {
    beginStop(format("tracking error %.2f m", error), x.tail<2>(), TrackerState::kAborted);
    return stopStep(dt, x.tail<2>());
  }
  if (!advancePhase(dt, x, error)) return stopStep(dt, x.tail<2>());

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
  out.body_deviation = path_->distanceToPlanned(wd::axlePose(x, chair_).head<2>());
  out.saturation_scale = sat.scale;
  out.reference_rate = rate_;
  return out;
}

}  // namespace wheelchair_controller
