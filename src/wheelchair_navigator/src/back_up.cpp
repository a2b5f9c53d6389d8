#include <wheelchair_core/path_direction.h>
#include <wheelchair_navigator/back_up.h>

#include <cmath>
#include <cstdio>

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
    if (it == trail_.rbegin() && step > config_.max_jump) return {};  // the trail is not here
    if (step < (back.size() == 1 ? config_.first_step : config_.spacing)) continue;
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

bool backUpHelps(bool route_from_chair, bool route_from_trail_end) {
  return route_from_trail_end && !route_from_chair;
}

namespace {
/// [m], [rad] a check holds for the chair standing where it was asked (it stands blocked).
constexpr double kSamePlace = 0.10;
constexpr double kSameHeading = 0.15;
}  // namespace

BackUpRecovery::BackUpRecovery(BackUpConfig config, RouteQuery query, Log log)
    : trail_(config), query_(std::move(query)), log_(std::move(log)) {}

BackUpRecovery::~BackUpRecovery() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  if (worker_.joinable()) worker_.join();
}

void BackUpRecovery::record(const Pose2D& pose) {
  std::lock_guard<std::mutex> lock(mutex_);
  trail_.record(pose);
}

bool BackUpRecovery::samePlace(const Check& check, const BlockedSituation& s) const {
  return gap(check.chair, s.chair) <= kSamePlace &&
         std::abs(wheelchair_core::angleDifference(check.chair.yaw, s.chair.yaw)) <= kSameHeading &&
         gap(check.goal, s.goal) <= kSamePlace &&
         std::abs(wheelchair_core::angleDifference(check.goal.yaw, s.goal.yaw)) <= kSameHeading;
}

std::vector<Pose2D> BackUpRecovery::offer(const BlockedSituation& situation) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (check_ && samePlace(*check_, situation)) {
    if (!check_->done || !check_->helps) return {};       // running, or backing does not help here
    std::vector<Pose2D> route = trail_.route(situation);  // from where the chair stands now
    check_.reset();                                       // taken: a later block is checked afresh
    return route;
  }
  if (running_ || stopping_) return {};  // a check for another place still runs
  Check check;
  check.chair = situation.chair;
  check.goal = situation.goal;
  check.route = trail_.route(situation);
  if (check.route.empty()) return {};  // no trail behind: nothing to back along
  check_ = check;
  if (worker_.joinable()) worker_.join();  // the last check's thread has ended (not running)
  running_ = true;
  worker_ = std::thread(&BackUpRecovery::run, this, std::move(check));
  return {};
}

void BackUpRecovery::run(Check check) {
  char where[64];
  std::snprintf(where, sizeof(where), "(%.2f, %.2f)", check.route.back().x, check.route.back().y);
  std::string end_detail, chair_detail, verdict;
  const bool from_end = query_(check.route.back(), check.goal, end_detail);
  // Only if the trail's end has a route: whether the chair's own pose lacks one.
  const bool from_chair = from_end && query_(std::nullopt, check.goal, chair_detail);
  check.helps = backUpHelps(from_chair, from_end);
  check.done = true;
  if (!from_end)
    verdict = std::string("back-up: no route from the trail's end ") + where +
              " either, the chair waits (" + end_detail + ")";
  else if (from_chair)
    verdict = "back-up: the chair's own pose has a route, no back-up";
  else
    verdict = std::string("back-up: the trail's end ") + where +
              " has a route the chair's pose lacks (" + chair_detail + "): backing out";
  if (log_) log_(verdict);
  std::lock_guard<std::mutex> lock(mutex_);
  if (check_ && gap(check_->chair, check.chair) < 1e-9 && !check_->done) check_ = check;
  running_ = false;
  idle_.notify_all();
}

void BackUpRecovery::waitIdle() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return !running_; });
}

}  // namespace wheelchair_navigator
