#include <wheelchair_core/polygon.h>
#include <wheelchair_display/drive_tracker.h>

#include <cmath>
#include <limits>

namespace wheelchair_display {
namespace {

using Phase = DriveView::Phase;
using wheelchair_core::Pose2D;

bool samePose(const Pose2D& a, const Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y) < 1e-6 && std::abs(a.yaw - b.yaw) < 1e-6;
}

}  // namespace

double remainingLength(const std::vector<Pose2D>& path, const Eigen::Vector2d& position,
                       size_t* segment) {
  if (path.empty()) return 0.0;
  if (path.size() == 1) return (path.front().position() - position).norm();
  size_t first = segment ? std::min(*segment, path.size() - 2) : 0;
  size_t best = first;
  double best_distance = std::numeric_limits<double>::infinity(), best_along = 0.0;
  for (size_t i = first; i + 1 < path.size(); ++i) {
    double along = 0.0;
    const double d = wheelchair_core::pointSegmentDistance(position, path[i].position(),
                                                           path[i + 1].position(), &along);
    if (d < best_distance - 1e-9) {
      best_distance = d;
      best = i;
      best_along = along;
    }
  }
  if (segment) *segment = best;
  double left = (path[best + 1].position() - path[best].position()).norm() - best_along;
  for (size_t i = best + 1; i + 1 < path.size(); ++i)
    left += (path[i + 1].position() - path[i].position()).norm();
  return std::max(0.0, left);
}

void DriveTracker::begin(Phase phase, const std::string& destination, const Pose2D& goal) {
  view_ = DriveView();
  view_.phase = phase;
  view_.destination = destination;
  goal_ = goal;
  route_.clear();
  segment_ = 0;
  position_.reset();
}

void DriveTracker::check(const std::string& destination, const Pose2D& goal, double) {
  begin(Phase::kChecking, destination, goal);
}

void DriveTracker::checked(const Pose2D& goal, bool reachable, double length,
                           const std::string& sentence, double now) {
  if (view_.phase != Phase::kChecking || !goal_ || !samePose(*goal_, goal)) return;
  if (!reachable) {
    end(Phase::kRefused, sentence, now);
    return;
  }
  view_.phase = Phase::kReachable;
  view_.distance = length;
}

void DriveTracker::cancelChoice() {
  if (view_.phase == Phase::kChecking || view_.phase == Phase::kReachable ||
      view_.phase == Phase::kRefused) {
    view_ = DriveView();
    goal_.reset();
  }
}

void DriveTracker::goal(const std::string& destination, const Pose2D& goal, double) {
  begin(Phase::kDriving, destination, goal);
}

void DriveTracker::route(const std::vector<Pose2D>& poses, double now) {
  if (view_.phase != Phase::kDriving) return;
  if (poses.empty()) {
    end(Phase::kRefused, "", now);
    return;
  }
  route_ = poses;
  segment_ = 0;
}

void DriveTracker::progress(const Eigen::Vector2d& position) {
  position_ = position;
  if (view_.phase == Phase::kDriving && !route_.empty())
    view_.distance = remainingLength(route_, position, &segment_);
}

void DriveTracker::arrived(double now, const std::string& sentence) {
  if (view_.phase == Phase::kDriving) end(Phase::kArrived, sentence, now);
}

void DriveTracker::heldUp(const std::string& sentence) {
  if (view_.phase == Phase::kDriving) view_.sentence = sentence;
}

void DriveTracker::ended(double now, double radius, const std::string& sentence) {
  if (goal_ && position_ && (*position_ - goal_->position()).norm() <= radius)
    arrived(now);
  else
    failed(now, sentence);
}

void DriveTracker::failed(double now, const std::string& sentence) {
  if (view_.phase == Phase::kDriving) end(Phase::kFailed, sentence, now);
}

void DriveTracker::refused(double now, const std::string& sentence) {
  if (view_.phase == Phase::kDriving) end(Phase::kRefused, sentence, now);
}

void DriveTracker::riderStopped(double now) {
  if (view_.phase == Phase::kDriving)
    end(Phase::kStoppedByRider, "", now);
  else
    cancelChoice();
}

void DriveTracker::tick(double now) {
  if (view_.outcome() && now - outcome_time_ > outcome_hold_) {
    view_ = DriveView();
    goal_.reset();
    route_.clear();
  }
}

void DriveTracker::end(Phase phase, const std::string& sentence, double now) {
  view_.phase = phase;
  view_.sentence = sentence;
  view_.distance = std::nan("");
  outcome_time_ = now;
  route_.clear();
}

}  // namespace wheelchair_display
