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

}  // namespace wheelchair_controller
