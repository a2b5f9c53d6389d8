#include <wheelchair_controller/motion_profile.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace wheelchair_controller {

double approachJerk(double v, double a, double v_target, const MotionLimits& limits, double dt) {
  const double j = limits.jerk, e = v_target - v;
  // Close enough: cancel the acceleration in one step (|change| <= j dt).
  if (std::abs(e) <= j * dt * dt && std::abs(a) <= j * dt) return -a / dt;
  const double dir = e > 0.0 ? 1.0 : -1.0;
  const double a_dir = dir * a, e_abs = std::abs(e);
  // Speed still gained while ramping the acceleration back to zero: a^2 / (2 j), plus one
  // step of a (the ramp starts on a step boundary).
  if (a_dir > 0.0 && a_dir * a_dir / (2.0 * j) + a_dir * dt >= e_abs) return -dir * j;
  if (a_dir < limits.accel) return dir * std::min(j, (limits.accel - a_dir) / dt);
  return 0.0;
}

ProfileSample integrateJerk(const ProfileSample& x, double j, double dt, double max_accel) {
  ProfileSample n;
  n.t = x.t + dt;
  n.a = std::clamp(x.a + j * dt, -max_accel, max_accel);
  const double a_mean = 0.5 * (x.a + n.a);
  n.v = x.v + a_mean * dt;
  n.s = x.s + x.v * dt + 0.5 * x.a * dt * dt + (n.a - x.a) * dt * dt / 6.0;
  return n;
}

JerkLimitedProfile::JerkLimitedProfile(double length, std::vector<double> speed_limit,
                                       const MotionLimits& limits, double v0, double dt)
    : length_(length), speed_limit_(std::move(speed_limit)), limits_(limits), dt_(dt) {
  if (!(length > 0.0) || speed_limit_.size() < 2 || !(limits.speed > 0.0) ||
      !(limits.accel > 0.0) || !(limits.jerk > 0.0) || !(dt > 0.0))
    throw std::invalid_argument("JerkLimitedProfile: non-positive length, limit or step");
  limit_ahead_ = speed_limit_;
  for (size_t i = limit_ahead_.size() - 1; i-- > 0;)
    limit_ahead_[i] = std::min(limit_ahead_[i], limit_ahead_[i + 1]);
  ProfileSample x;
  x.v = std::max(0.0, v0);
  samples_.push_back(x);
  constexpr double kEndTolerance = 1e-3;  // [m], [m/s]
  const double max_time = 20.0 * (length / limits.speed + limits.speed / limits.accel +
                                  limits.accel / limits.jerk + x.v / limits.accel) +
                          10.0;
  while (x.t < max_time) {
    const bool at_rest = x.v < 0.1 * kEndTolerance && std::abs(x.a) < kEndTolerance;
    if (samples_.size() > 1 && at_rest) break;
    if (length_ - x.s < kEndTolerance && x.v < kEndTolerance) break;
    // Greedy: the fastest jerk toward the cruise speed that still leaves a safe braking.
    const double j_want = approachJerk(x.v, x.a, limits.speed, limits, dt_);
    const double j_brake = approachJerk(x.v, x.a, 0.0, limits, dt_);
    double j = j_want;
    if (!canBrake(integrateJerk(x, j_want, dt_, limits.accel))) {
      double lo = std::min(j_brake, j_want), hi = j_want;  // lo: the braking profile's own step
      for (int i = 0; i < 6; ++i) {
        const double mid = 0.5 * (lo + hi);
        (canBrake(integrateJerk(x, mid, dt_, limits.accel)) ? lo : hi) = mid;
      }
      j = lo;
    }
    x = integrateJerk(x, j, dt_, limits.accel);
    x.v = std::max(0.0, x.v);
    samples_.push_back(x);
  }
  samples_.back().s = std::min(samples_.back().s, length_);
  samples_.back().v = 0.0;
  samples_.back().a = 0.0;
}

double JerkLimitedProfile::limitAt(double s) const {
  const double pos = std::clamp(s / length_, 0.0, 1.0) * (speed_limit_.size() - 1);
  const size_t i = std::min(static_cast<size_t>(pos), speed_limit_.size() - 2);
  const double f = pos - i;
  return (1.0 - f) * speed_limit_[i] + f * speed_limit_[i + 1];
}

bool JerkLimitedProfile::canBrake(const ProfileSample& start) const {
  constexpr double kSlack = 1e-3;
  const double kStep = dt_;  // the same discretization as the profile itself
  ProfileSample x = start;
  // Upper bound of the braking distance (ramp to -accel, hold, release); with it the check is
  // decided at once when the speed is below every limit ahead.
  const double a = limits_.accel, j = limits_.jerk;
  const double positive_a = std::max(0.0, x.a);
  const double v_peak = x.v + positive_a * positive_a / (2.0 * j);
  const double bound = v_peak * v_peak / (2.0 * a) + v_peak * (a / j + positive_a / j);
  const size_t i0 =
      std::min(limit_ahead_.size() - 1,
               static_cast<size_t>(std::max(0.0, x.s) / length_ * (limit_ahead_.size() - 1)));
  if (v_peak <= limit_ahead_[i0] && x.s + bound <= length_) return true;
  for (int i = 0; i < 100000 && (x.v > 0.0 || x.a > 0.0); ++i) {
    if (x.s > length_ + kSlack) return false;
    if (x.s < length_ && x.v > limitAt(x.s) + kSlack) return false;
    x = integrateJerk(x, approachJerk(x.v, x.a, 0.0, limits_, kStep), kStep, limits_.accel);
  }
  return x.s <= length_ + kSlack;
}

ProfileSample JerkLimitedProfile::at(double t) const {
  if (t <= 0.0) return samples_.front();
  if (t >= duration()) return samples_.back();
  const size_t i = std::min(static_cast<size_t>(t / dt_), samples_.size() - 2);
  const double f = (t - samples_[i].t) / dt_;
  const ProfileSample &a = samples_[i], &b = samples_[i + 1];
  return {t, a.s + f * (b.s - a.s), a.v + f * (b.v - a.v), a.a + f * (b.a - a.a)};
}

}  // namespace wheelchair_controller
