// What the controller drives for a planned path, exported so that the planner's footprint gate
// checks exactly this motion (the two cannot drift): the path split at its cusps into pieces
// driven forwards or in reverse (wheelchair_core/path_direction.h: a pose's yaw is the chair's
// heading), each piece as the controller smooths it, its phases (in-place rotation at the start,
// each piece with its tangent heading, a stop at every cusp, in-place rotation to the goal
// heading) with the controller's own tolerances, and the poses base_link takes.
#pragma once

#include <wheelchair_controller/smooth_path.h>
#include <wheelchair_controller/tracker_config.h>
#include <wheelchair_core/path_direction.h>
#include <wheelchair_core/pose2d.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace wheelchair_controller {

using wheelchair_core::Direction;

constexpr double kMinPathLength = 0.01;  ///< [m] shorter paths are "zero-length"

/// One piece of a plan driven one way: its smooth path (positions in the order of motion, so
/// `heading` is the direction of motion) and the direction. In reverse the chair faces the other
/// way: its heading is the tangent + pi.
struct DrivenPiece {
  std::shared_ptr<const SmoothPath> path;
  Direction direction = Direction::kForward;

  bool reverse() const { return direction == Direction::kReverse; }
  /// The chair's heading at arc length s (unwrapped along the piece).
  double bodyHeading(double s) const { return path->at(s).heading + (reverse() ? M_PI : 0.0); }
  double startHeading() const { return bodyHeading(0.0); }
  double endHeading() const { return bodyHeading(path->length()); }
};

/// A plan as the controller drives it: its pieces in order (cusps between them) and the heading
/// the chair must have at the goal (the last pose's yaw).
struct DrivenPlan {
  std::vector<DrivenPiece> pieces;
  double goal_heading = 0.0;

  size_t cusps() const { return pieces.empty() ? 0 : pieces.size() - 1; }
  /// Distance from a point to the planned polyline (as given, before smoothing), all pieces.
  double distanceToPlanned(const Eigen::Vector2d& point) const;
};

/// The plan the controller tracks for `path` (base_link poses in map), or nullopt with the
/// reason the controller refuses it (empty, non-finite, zero-length, a piece between two cusps
/// shorter than kMinPathLength).
std::optional<DrivenPlan> drivenPlan(const std::vector<Pose2D>& path, std::string& rejection);

/// True if a chair at rest with heading `yaw` first rotates in place to the piece's start
/// heading: at the start beyond start_heading_tolerance, at a cusp (`at_cusp`) beyond
/// cusp_heading_tolerance.
bool rotatesBeforePiece(const DrivenPiece& piece, double yaw, const TrackerConfig& config,
                        bool at_cusp = false);
/// True if the chair rotates in place to the goal heading at the end of the plan.
bool rotatesToGoalHeading(const DrivenPlan& plan, const TrackerConfig& config);

/// One pose of the motion and the phase it belongs to.
struct SweepPose {
  enum class Phase { kStartRotation, kPath, kCuspRotation, kGoalRotation };
  Pose2D pose;
  Phase phase = Phase::kPath;
  Direction direction = Direction::kForward;  ///< of the piece (kPath, kCuspRotation: the next)
  int piece = 0;                              ///< index of the piece it belongs to or precedes
};

/// How finely the motion is sampled.
struct SweepSampling {
  double max_step = 0.02;                ///< [m] between poses along the path
  double max_turn = 2.0 * M_PI / 180.0;  ///< [rad] between poses
};

/// Poses of base_link when the controller drives `path` from `start` (the chair's pose, yaw
/// included): the rotation from the start yaw to the first piece's start heading (at rest the
/// controller rotates in place when off by more than start_heading_tolerance; below it the chair
/// turns while it drives off, sweeping about the same poses: included either way), each smoothed
/// piece with its body heading (the controller keeps the axle on it, off-tracking compensated,
/// forwards or in reverse), at each cusp the rotation from the heading the chair stops with to
/// the next piece's start heading (included either way, as at the start), and the rotation to
/// the goal heading when rotatesToGoalHeading(). Empty if the controller would refuse the path.
std::vector<SweepPose> executedSweep(const Pose2D& start, const std::vector<Pose2D>& path,
                                     const TrackerConfig& config = TrackerConfig(),
                                     const SweepSampling& sampling = SweepSampling());

/// Poses of an in-place rotation about (x, y) from yaw0 to yaw1 the short way, at most
/// `max_turn` apart, both ends included.
std::vector<Pose2D> rotationInPlace(double x, double y, double yaw0, double yaw1, double max_turn);

}  // namespace wheelchair_controller
