#include <wheelchair_base_driver/wheel_motion_check.h>

#include <cstdio>

namespace wheelchair_base_driver {

namespace {
std::string format(const char* fmt, const char* wheel, double a, double b) {
  char text[200];
  std::snprintf(text, sizeof(text), fmt, wheel, a, b);
  return text;
}
bool opposite(double rate, double torque) { return rate * torque < 0.0; }
}  // namespace

void WheelMotionCheck::reset(double now, double left_angle, double right_angle) {
  const std::array<double, 2> angles{left_angle, right_angle};
  for (int i = 0; i < 2; ++i) {
    Wheel& w = wheels_[i];
    w = Wheel();
    w.angle = angles[i];
    w.counted_at = now;
    w.other_at_count = angles[1 - i];
  }
}

void WheelMotionCheck::onEncoder(double stamp, double left_angle, double right_angle) {
  const std::array<double, 2> angles{left_angle, right_angle};
  for (int i = 0; i < 2; ++i) {
    Wheel& w = wheels_[i];
    if (angles[i] != w.angle || !std::isfinite(w.counted_at)) {
      w.angle = angles[i];
      w.counted_at = stamp;
      w.other_at_count = angles[1 - i];
    }
  }
}

WheelVerdict WheelMotionCheck::check(double now, bool counting, const WheelState& left,
                                     const WheelState& right) {
  WheelVerdict v = checkWheel("left", wheels_[0], left, right, now, counting);
  if (v.fault != WheelFault::kNone) return v;
  return checkWheel("right", wheels_[1], right, left, now, counting);
}

WheelVerdict WheelMotionCheck::checkWheel(const char* name, Wheel& w, const WheelState& s,
                                          const WheelState& other, double now, bool counting) {
  const double pushed = std::abs(s.torque) >= config_.stall_torque;
  if (!pushed) w.pushed_since = NAN;
  if (pushed && !std::isfinite(w.pushed_since)) w.pushed_since = now;
  const bool against =
      pushed && opposite(s.rate, s.torque) && std::abs(s.rate) > config_.encoder_check_rate;
  if (!against) w.against_since = NAN;
  if (against && !std::isfinite(w.against_since)) {
    w.against_since = now;
    w.against_rate = std::abs(s.rate);
  }
  if (!counting || !std::isfinite(w.counted_at)) return {};  // a silent MC is another fault

  const double still = now - w.counted_at;
  const double other_turned = std::abs(other.angle - w.other_at_count);
  // The angle rule also needs the other wheel to have turned faster than encoder_check_rate on
  // average meanwhile: a turn about a standing inner wheel (the other slow) is a real motion.
  const bool other_fast = other_turned >= config_.encoder_check_rate * still;
  // And the wheel's motor must push it (|torque| >= encoder_check_torque): a wheel that stands
  // while the other turns under the driving torques of a pivot (rolling resistance and the
  // comfort acceleration need < 6 N m) is the chair turning about it; with a frozen encoder the
  // controller, seeing the wheel stand, pushes it hard within a few frames (36 N m in 0.09 s in
  // the frozen_encoder system test).
  const bool pushed_to_move = std::abs(s.torque) >= config_.encoder_check_torque;
  if (pushed_to_move &&
      ((still > config_.encoder_check_time && std::abs(other.rate) > config_.encoder_check_rate) ||
       (other_turned >= config_.encoder_check_angle && other_fast)))
    return {
        WheelFault::kFrozenEncoder,
        format("%s encoder did not count for %.2f s while the other wheel turned %.2f rad", name,
               still, other_turned) +
            format(" (%s torque %.1f N m; the other at %.2f rad/s)", "its", s.torque, other.rate)};
  if (pushed && now - std::max(w.pushed_since, w.counted_at) >= config_.stall_time)
    return {WheelFault::kStalled, format("%s wheel did not turn for %.2f s under %.1f N m", name,
                                         now - std::max(w.pushed_since, w.counted_at), s.torque)};
  if (against && now - w.against_since >= config_.stall_time && std::abs(s.rate) > w.against_rate)
    return {WheelFault::kAgainstCommand,
            format("%s wheel sped up to %.2f rad/s against %.1f N m", name, s.rate, s.torque)};
  return {};
}

}  // namespace wheelchair_base_driver
