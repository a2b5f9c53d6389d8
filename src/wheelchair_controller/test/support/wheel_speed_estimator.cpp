#include <wheelchair_controller_test/wheel_speed_estimator.h>

#include <cmath>

namespace wheelchair_controller {

Eigen::Vector2d WheelSpeedEstimator::update(double stamp, const Eigen::Vector2d& wheel_angles) {
  if (!std::isfinite(stamp) || !wheel_angles.allFinite() || (have_last_ && stamp <= last_stamp_)) {
    have_last_ = false;
    eta_.setZero();
    return eta_;
  }
  if (have_last_) {
    const double dt = stamp - last_stamp_;
    const Eigen::Vector2d raw = (wheel_angles - last_angles_) / dt;
    const double alpha = time_constant_ > 0.0 ? dt / (time_constant_ + dt) : 1.0;
    eta_ += alpha * (raw - eta_);
  }
  have_last_ = true;
  last_stamp_ = stamp;
  last_angles_ = wheel_angles;
  return eta_;
}

}  // namespace wheelchair_controller
