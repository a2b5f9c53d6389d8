#include <wheelchair_core/path_direction.h>
#include <wheelchair_navigator/back_up.h>

#include <cmath>

namespace wheelchair_navigator {

namespace {
double gap(const Pose2D& a, const Pose2D& b) { return std::hypot(b.x - a.x, b.y - a.y); }
}  // namespace

BackUpTrail::BackUpTrail(BackUpConfig config) : config_(config) {}

void BackUpTrail::record(const Pose2D& pose) {
  if (!pose.isFinite()) return;
  if (trail_.empty()) {
    trail_.push_back(pose);
    return;
  }
  const Pose2D& last = trail_.back();
  const double step = gap(last, pose);
  if (step > config_.max_jump) {  // relocalized: the poses before are not a way it drove
    trail_.clear();
    trail_.push_back(pose);
    return;
  }
  if (step < config_.spacing) return;
  // Judged by the heading it arrived with (a turn on the spot between records changes it).
  const Pose2D from{last.x, last.y, pose.yaw};
  if (wheelchair_core::stepDirection(from, pose, wheelchair_core::Direction::kForward) ==
      wheelchair_core::Direction::kReverse) {  // it backed: only the forward stretch is kept
    trail_.clear();
  }
  trail_.push_back(pose);
  while (trail_.size() > 2 && length() - gap(trail_[0], trail_[1]) >= config_.keep)
    trail_.pop_front();
}

double BackUpTrail::length() const {
  double total = 0.0;
  for (size_t i = 1; i < trail_.size(); ++i) total += gap(trail_[i - 1], trail_[i]);
  return total;
}

std::vector<Pose2D> BackUpTrail::route(const BlockedSituation& situation) const {
  std::vector<Pose2D> back{situation.chair};
  double along = 0.0;
  for (auto it = trail_.rbegin(); it != trail_.rend() && along < config_.distance; ++it) {
    const double step = gap(back.back(), *it);
    if (back.size() == 1 && step > config_.max_jump) return {};  // the trail is not here
    if (step < config_.spacing) continue;
    // Not beyond `distance`: the last pose is where the trail passes it.
    if (along + step > config_.distance) {
      const double f = (config_.distance - along) / step;
      const Pose2D& from = back.back();
      back.push_back({from.x + f * (it->x - from.x), from.y + f * (it->y - from.y), it->yaw});
      along = config_.distance;
      break;
    }
    back.push_back(*it);
    along += step;
  }
  if (along < config_.min_distance) return {};
  return back;
}

}  // namespace wheelchair_navigator
