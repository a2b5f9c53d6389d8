#include <wheelchair_base_driver/encoder_odometry.h>

#include <cmath>

namespace wheelchair_base_driver {

namespace core = wheelchair_core;
namespace protocol = wheelchair_can::protocol;

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
  const core::WheelBase base = geometry_.base();
  const core::BodyTwist twist = core::bodyTwist({state_.right_rate, state_.left_rate}, base);
  state_.v = twist.v;
  state_.omega = twist.omega;
  // The arc rolled since the last sample, exact for a constant twist over dt.
  state_.pose = core::integrateArc(
      state_.pose,
      core::bodyMotion(base.wheel_radius * d_right, base.wheel_radius * d_left, base.half_track));
  return true;
}

}  // namespace wheelchair_base_driver
