#include <wheelchair_base_driver/encoder_odometry.h>

#include <cmath>

namespace wheelchair_base_driver {

Twist2D bodyTwistFromWheelRates(double left_rate, double right_rate, const WheelGeometry& g) {
  // Eq. 10-11 (kinematics of P): v = r (psi_r_dot + psi_l_dot)/2, omega = r (psi_r_dot -
  // psi_l_dot)/(2b).
  return {g.wheel_radius * (right_rate + left_rate) / 2.0,
          g.wheel_radius * (right_rate - left_rate) / (2.0 * g.half_track)};
}

bool EncoderOdometry::update(const protocol::EncoderCounts& counts, double stamp) {
  if (!has_reference_) {
    has_reference_ = true;
    reference_ = counts;
    state_.stamp = stamp;
    return true;
  }
  // Counts are absolute: a sample with no elapsed time is folded into the next one.
  if (stamp <= state_.stamp) return true;
  const double dt = stamp - state_.stamp;
  const double rad_per_count = 2.0 * M_PI / geometry_.counts_per_rev;
  const double d_left = protocol::encoderDelta(counts.left, reference_.left) * rad_per_count;
  const double d_right = protocol::encoderDelta(counts.right, reference_.right) * rad_per_count;
  if (std::abs(d_left) > geometry_.max_wheel_rate * dt ||
      std::abs(d_right) > geometry_.max_wheel_rate * dt) {
    resync();
    return false;
  }
  reference_ = counts;
  state_.stamp = stamp;
  state_.left_angle += d_left;
  state_.right_angle += d_right;
  state_.left_rate = d_left / dt;
  state_.right_rate = d_right / dt;
  const Twist2D twist = bodyTwistFromWheelRates(state_.left_rate, state_.right_rate, geometry_);
  state_.v = twist.v;
  state_.omega = twist.omega;
  // Exact integration over dt assuming constant twist (midpoint heading for the chord).
  const double d_theta = twist.omega * dt;
  const double d_s = twist.v * dt;
  const double chord = std::abs(d_theta) < 1e-9 ? d_s : d_s * std::sin(d_theta / 2) / (d_theta / 2);
  state_.x += chord * std::cos(state_.theta + d_theta / 2);
  state_.y += chord * std::sin(state_.theta + d_theta / 2);
  state_.theta = std::remainder(state_.theta + d_theta, 2.0 * M_PI);
  return true;
}

}  // namespace wheelchair_base_driver
