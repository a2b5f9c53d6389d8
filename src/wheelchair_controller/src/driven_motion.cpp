#include <wheelchair_controller/driven_motion.h>

#include <algorithm>
#include <exception>
#include <limits>

namespace wheelchair_controller {

double DrivenPlan::distanceToPlanned(const Eigen::Vector2d& point) const {
  double best = std::numeric_limits<double>::infinity();
  for (const DrivenPiece& piece : pieces)
    best = std::min(best, piece.path->distanceToPlanned(point));
  return best;
}

std::optional<DrivenPlan> drivenPlan(const std::vector<Pose2D>& path, std::string& rejection) {
  rejection = pathRejectionReason(path, kMinPathLength);
  if (!rejection.empty()) return std::nullopt;
  DrivenPlan plan;
  plan.goal_heading = path.back().yaw;
  try {
    const std::vector<wheelchair_core::PathPiece> pieces = wheelchair_core::splitAtCusps(path);
    for (size_t k = 0; k < pieces.size(); ++k) {
      const wheelchair_core::PathPiece& piece = pieces[k];
      const std::vector<Pose2D> poses(path.begin() + piece.begin, path.begin() + piece.end + 1);
      if (!pathRejectionReason(poses, kMinPathLength).empty()) {
        rejection = "path refused: a piece between two cusps is shorter than 1 cm";
        return std::nullopt;
      }
      const CuspEnds cusps{k > 0, k + 1 < pieces.size()};
      plan.pieces.push_back(
          {std::make_shared<SmoothPath>(poses, 0.05, 0.15, cusps), piece.direction});
    }
  } catch (const std::exception& e) {
    rejection = std::string("path refused: ") + e.what();
    return std::nullopt;
  }
  return plan;
}

bool rotatesBeforePiece(const DrivenPiece& piece, double yaw, const TrackerConfig& config,
                        bool at_cusp) {
  return std::abs(std::remainder(piece.startHeading() - yaw, 2.0 * M_PI)) >
         (at_cusp ? config.cusp_heading_tolerance : config.start_heading_tolerance);
}

bool rotatesToGoalHeading(const DrivenPlan& plan, const TrackerConfig& config) {
  return std::abs(std::remainder(plan.goal_heading - plan.pieces.back().endHeading(), 2.0 * M_PI)) >
         config.goal_heading_tolerance;
}

std::vector<Pose2D> rotationInPlace(double x, double y, double yaw0, double yaw1, double max_turn) {
  const double delta = std::remainder(yaw1 - yaw0, 2.0 * M_PI);
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / max_turn)));
  std::vector<Pose2D> out;
  for (int k = 0; k <= n; ++k) out.push_back({x, y, yaw0 + delta * k / n});
  return out;
}

std::vector<SweepPose> executedSweep(const Pose2D& start, const std::vector<Pose2D>& path,
                                     const TrackerConfig& config, const SweepSampling& sampling) {
  std::vector<SweepPose> sweep;
  std::string rejection;
  const std::optional<DrivenPlan> plan = drivenPlan(path, rejection);
  if (!plan) return sweep;
  Pose2D prev = start;
  for (size_t k = 0; k < plan->pieces.size(); ++k) {
    const DrivenPiece& piece = plan->pieces[k];
    const int index = static_cast<int>(k);
    const SweepPose::Phase turn =
        k == 0 ? SweepPose::Phase::kStartRotation : SweepPose::Phase::kCuspRotation;
    for (const Pose2D& p :
         rotationInPlace(prev.x, prev.y, prev.yaw, piece.startHeading(), sampling.max_turn))
      sweep.push_back({p, turn, piece.direction, index});
    const double length = piece.path->length();
    const auto bodyAt = [&](double s) {
      const PathPoint q = piece.path->at(s);
      return Pose2D{q.position.x(), q.position.y(), piece.bodyHeading(s)};
    };
    prev = bodyAt(0.0);
    sweep.push_back({prev, SweepPose::Phase::kPath, piece.direction, index});
    const int steps = std::max(1, static_cast<int>(std::ceil(length / sampling.max_step)));
    for (int i = 1; i <= steps; ++i) {
      const double s0 = length * (i - 1) / steps, s1 = length * i / steps;
      const Pose2D next = bodyAt(s1);
      const int sub = std::max(
          1, static_cast<int>(std::ceil(std::abs(next.yaw - prev.yaw) / sampling.max_turn)));
      for (int j = 1; j <= sub; ++j)
        sweep.push_back(
            {bodyAt(s0 + (s1 - s0) * j / sub), SweepPose::Phase::kPath, piece.direction, index});
      prev = next;
    }
  }
  if (rotatesToGoalHeading(*plan, config)) {
    const int last = static_cast<int>(plan->pieces.size()) - 1;
    for (const Pose2D& p :
         rotationInPlace(prev.x, prev.y, prev.yaw, plan->goal_heading, sampling.max_turn))
      sweep.push_back({p, SweepPose::Phase::kGoalRotation, plan->pieces.back().direction, last});
  }
  return sweep;
}

}  // namespace wheelchair_controller
