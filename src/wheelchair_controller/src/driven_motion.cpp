#include <wheelchair_controller/driven_motion.h>

#include <algorithm>
#include <exception>

namespace wheelchair_controller {

std::shared_ptr<const SmoothPath> drivenPath(const std::vector<Pose2D>& path,
                                             std::string& rejection) {
  rejection = pathRejectionReason(path, kMinPathLength);
  if (!rejection.empty()) return nullptr;
  try {
    return std::make_shared<SmoothPath>(path);
  } catch (const std::exception& e) {
    rejection = std::string("path refused: ") + e.what();
  }
  return nullptr;
}

bool rotatesBeforePath(const SmoothPath& path, double yaw, const TrackerConfig& config) {
  return std::abs(std::remainder(path.at(0.0).heading - yaw, 2.0 * M_PI)) >
         config.start_heading_tolerance;
}

bool rotatesToGoalHeading(const SmoothPath& path, const TrackerConfig& config) {
  return std::abs(std::remainder(path.goalHeading() - path.at(path.length()).heading, 2.0 * M_PI)) >
         config.goal_heading_tolerance;
}

std::vector<Pose2D> rotationInPlace(double x, double y, double yaw0, double yaw1, double max_turn) {
  const double delta = std::remainder(yaw1 - yaw0, 2.0 * M_PI);
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / max_turn)));
  std::vector<Pose2D> out;
  for (int k = 0; k <= n; ++k) out.push_back({x, y, yaw0 + delta * k / n});
  return out;
}

std::vector<SweepPose> executedSweep(const Pose2D& start, const std::vector<Pose2D>& plan,
                                     const TrackerConfig& config, const SweepSampling& sampling) {
  std::vector<SweepPose> sweep;
  std::string rejection;
  const std::shared_ptr<const SmoothPath> path = drivenPath(plan, rejection);
  if (!path) return sweep;
  for (const Pose2D& p :
       rotationInPlace(start.x, start.y, start.yaw, path->at(0.0).heading, sampling.max_turn))
    sweep.push_back({p, SweepPose::Phase::kStartRotation});
  const double length = path->length();
  const auto bodyAt = [&](double s) {
    const PathPoint q = path->at(s);
    return Pose2D{q.position.x(), q.position.y(), q.heading};
  };
  Pose2D prev = bodyAt(0.0);
  sweep.push_back({prev, SweepPose::Phase::kPath});
  const int steps = std::max(1, static_cast<int>(std::ceil(length / sampling.max_step)));
  for (int i = 1; i <= steps; ++i) {
    const double s0 = length * (i - 1) / steps, s1 = length * i / steps;
    const Pose2D next = bodyAt(s1);
    const int sub =
        std::max(1, static_cast<int>(std::ceil(std::abs(next.yaw - prev.yaw) / sampling.max_turn)));
    for (int k = 1; k <= sub; ++k)
      sweep.push_back({bodyAt(s0 + (s1 - s0) * k / sub), SweepPose::Phase::kPath});
    prev = next;
  }
  if (rotatesToGoalHeading(*path, config)) {
    for (const Pose2D& p :
         rotationInPlace(prev.x, prev.y, prev.yaw, path->goalHeading(), sampling.max_turn))
      sweep.push_back({p, SweepPose::Phase::kGoalRotation});
  }
  return sweep;
}

}  // namespace wheelchair_controller
