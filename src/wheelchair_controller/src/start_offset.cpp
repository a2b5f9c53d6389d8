#include <wheelchair_controller/start_offset.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_controller {

OffsetDecayTrajectory::OffsetDecayTrajectory(std::shared_ptr<const OutputTrajectory> base,
                                             const Eigen::Vector2d& offset, double decay_time)
    : base_(std::move(base)), offset_(offset), decay_time_(std::max(decay_time, 1e-3)) {}

OutputReference OffsetDecayTrajectory::at(double t) const {
  OutputReference r = base_->at(t);
  const double x = std::clamp(t / decay_time_, 0.0, 1.0), T = decay_time_;
  const double s = x * x * x * (10.0 - 15.0 * x + 6.0 * x * x);
  const double ds = 30.0 * x * x * (1.0 - x) * (1.0 - x) / T;
  const double dds = 60.0 * x * (1.0 - x) * (1.0 - 2.0 * x) / (T * T);
  r.position += (1.0 - s) * offset_;
  r.velocity -= ds * offset_;
  r.acceleration -= dds * offset_;
  return r;
}

double offsetDecayTime(double offset, const MotionLimits& limits, double duration) {
  const double by_accel = std::sqrt(10.0 / std::sqrt(3.0) * offset / limits.accel);
  const double by_jerk = std::cbrt(60.0 * offset / limits.jerk);
  return std::min(std::max(by_accel, by_jerk), duration);
}

std::shared_ptr<const OutputTrajectory> startingFrom(std::shared_ptr<const OutputTrajectory> base,
                                                     const Eigen::Vector2d& y,
                                                     const MotionLimits& limits,
                                                     double min_offset) {
  const Eigen::Vector2d offset = y - base->at(0.0).position;
  if (offset.norm() <= min_offset) return base;
  const double T = offsetDecayTime(offset.norm(), limits, base->duration());
  return std::make_shared<OffsetDecayTrajectory>(std::move(base), offset, T);
}

namespace {

/// The quintic smoothstep s(x) = 10x^3 - 15x^4 + 6x^5, its integral S and derivative s'.
double smoothstep(double x) { return x * x * x * (10.0 - 15.0 * x + 6.0 * x * x); }
double smoothstepIntegral(double x) { return x * x * x * x * (2.5 - 3.0 * x + x * x); }
double smoothstepSlope(double x) { return 30.0 * x * x * (1.0 - x) * (1.0 - x); }

}  // namespace

RestartFromRestTrajectory::RestartFromRestTrajectory(std::shared_ptr<const OutputTrajectory> base,
                                                     double t0, double ramp_time)
    : base_(std::move(base)),
      t0_(std::clamp(t0, 0.0, base_->duration())),
      ramp_(std::max(ramp_time, 1e-3)) {
  const double left = base_->duration() - t0_;
  if (left >= 0.5 * ramp_) {
    duration_ = left + 0.5 * ramp_;
    return;
  }
  double lo = 0.0, hi = 1.0;  // T S(x) = left within the ramp (S increases on [0, 1])
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (ramp_ * smoothstepIntegral(mid) < left ? lo : hi) = mid;
  }
  duration_ = hi * ramp_;
}

double RestartFromRestTrajectory::baseTime(double t, double& rate, double& rate_dot) const {
  double tau;
  if (t < ramp_) {
    const double x = std::max(t, 0.0) / ramp_;
    tau = t0_ + ramp_ * smoothstepIntegral(x);
    rate = smoothstep(x);
    rate_dot = smoothstepSlope(x) / ramp_;
  } else {
    tau = t0_ + 0.5 * ramp_ + (t - ramp_);
    rate = 1.0;
    rate_dot = 0.0;
  }
  if (tau >= base_->duration()) {
    rate = rate_dot = 0.0;
    return base_->duration();
  }
  return tau;
}

OutputReference RestartFromRestTrajectory::at(double t) const {
  double rate, rate_dot;
  const OutputReference r = base_->at(baseTime(t, rate, rate_dot));
  OutputReference out = r;
  out.velocity = rate * r.velocity;
  out.acceleration = rate * rate * r.acceleration + rate_dot * r.velocity;
  return out;
}

double RestartFromRestTrajectory::heading(double t) const {
  double rate, rate_dot;
  return base_->heading(baseTime(t, rate, rate_dot));
}

double restartRampTime(double speed, const MotionLimits& limits) {
  const double v = std::abs(speed);
  return std::max({0.5, 1.875 * v / limits.accel, std::sqrt(5.774 * v / limits.jerk)});
}

double nearestTime(const OutputTrajectory& base, const Eigen::Vector2d& y, double from, double to,
                   double step) {
  from = std::clamp(from, 0.0, base.duration());
  to = std::clamp(to, from, base.duration());
  const auto distance = [&](double t) { return (base.at(t).position - y).norm(); };
  double best = from, best_distance = distance(from);
  for (double t = from + step; t < to + step; t += step) {
    const double d = distance(std::min(t, to));
    if (d < best_distance) best = std::min(t, to), best_distance = d;
  }
  for (double h = 0.5 * step; h > 1e-4; h *= 0.5) {  // refine within the coarse step
    for (const double t : {std::max(from, best - h), std::min(to, best + h)}) {
      const double d = distance(t);
      if (d < best_distance) best = t, best_distance = d;
    }
  }
  return best;
}

}  // namespace wheelchair_controller
