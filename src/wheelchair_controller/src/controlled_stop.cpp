#include <wheelchair_controller/controlled_stop.h>

#include <cmath>

namespace wheelchair_controller {
namespace wd = wheelchair_description;

ControlledStop::ControlledStop(const ChairParams& chair, const StopConfig& config)
    : chair_(chair), config_(config) {}

void ControlledStop::start(const Eigen::Vector2d& eta, double accel, double yaw_accel) {
  const Eigen::Vector2d body =
      wd::bodyVelocity(eta.allFinite() ? eta : Eigen::Vector2d::Zero(), chair_);
  linear_ = {0.0, 0.0, body(0), accel};
  angular_ = {0.0, 0.0, body(1), yaw_accel};
  const auto time_to_rest = [](const ProfileSample& x, const MotionLimits& l) {
    return std::abs(x.v) / l.accel + 2.0 * l.accel / l.jerk + std::abs(x.a) / l.jerk;
  };
  deadline_ =
      std::max(time_to_rest(linear_, config_.linear), time_to_rest(angular_, config_.angular)) +
      config_.extra_time;
  elapsed_ = 0.0;
  finished_ = false;
}

WheelCommand ControlledStop::step(const Eigen::Vector2d& eta, double dt) {
  elapsed_ += dt;
  if (finished_ || !eta.allFinite() || elapsed_ > deadline_) {
    finished_ = true;
    return {};
  }
  const auto advance = [dt](ProfileSample& x, const MotionLimits& l) {
    x = integrateJerk(x, approachJerk(x.v, x.a, 0.0, l, dt), dt, l.accel);
  };
  advance(linear_, config_.linear);
  advance(angular_, config_.angular);
  const bool ramp_done = std::abs(linear_.v) < 1e-4 && std::abs(angular_.v) < 1e-4;
  if (ramp_done && eta.cwiseAbs().maxCoeff() * chair_.wheel_radius < config_.rest_speed) {
    finished_ = true;
    return {};
  }
  // eta_ref, eta_dot_ref of the ramp (wheelSpeeds is linear in (v, w)); f1, f2 do not depend
  // on the pose (rotation invariance), so q = 0 serves.
  const Eigen::Vector2d eta_ref = wd::wheelSpeeds(linear_.v, angular_.v, chair_);
  const Eigen::Vector2d eta_dot_ref = wd::wheelSpeeds(linear_.a, angular_.a, chair_);
  const Eigen::Vector2d u = eta_dot_ref + config_.velocity_gain * (eta_ref - eta);
  WheelCommand cmd;
  cmd.brake = false;
  cmd.torque = computedTorque(Vector5::Zero(), eta, u, chair_);
  if (config_.compensate_rolling_resistance) cmd.torque += rollingResistanceTorque(eta, chair_);
  return cmd;
}

}  // namespace wheelchair_controller
