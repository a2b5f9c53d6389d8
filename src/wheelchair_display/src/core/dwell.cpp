#include <wheelchair_display/dwell.h>

#include <algorithm>

namespace wheelchair_display {

DwellTimer::DwellTimer(double dwell_time, double radius)
    : dwell_time_(dwell_time), radius_(radius) {}

void DwellTimer::reset() {
  target_ = kNoTarget;
  fired_target_ = kNoTarget;
  resting_ = false;
}

void DwellTimer::rest(const Eigen::Vector2d& pointer) {
  reset();
  resting_ = true;
  anchor_ = pointer;
}

DwellTimer::State DwellTimer::update(double now, const Eigen::Vector2d& pointer, int target) {
  State state;
  if (resting_) {
    if ((pointer - anchor_).norm() <= radius_) return state;
    resting_ = false;
    target_ = kNoTarget;
  }
  if (target != fired_target_) fired_target_ = kNoTarget;  // it left the chosen target: re-arm
  const bool moved_away = (pointer - anchor_).norm() > radius_;
  if (target != target_ || moved_away) {
    target_ = target;
    start_ = now;
    anchor_ = pointer;
  }
  state.target = target_;
  if (target_ == kNoTarget || target_ == fired_target_) return state;
  state.progress = std::clamp((now - start_) / dwell_time_, 0.0, 1.0);
  if (now - start_ >= dwell_time_ - 1e-9) {
    state.fired = true;
    state.progress = 0.0;
    fired_target_ = target_;
  }
  return state;
}

}  // namespace wheelchair_display
