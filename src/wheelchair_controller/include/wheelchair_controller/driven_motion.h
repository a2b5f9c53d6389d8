// What the controller drives for a planned path, exported so that the planner's footprint gate
// checks exactly this motion (the two cannot drift): the path as the controller smooths it, its
// phases (in-place rotation at the start, the path with its tangent heading, in-place rotation
// to the goal heading) with the controller's own tolerances, and the poses base_link takes.
#pragma once

#include <wheelchair_controller/smooth_path.h>
#include <wheelchair_controller/tracker_config.h>
#include <wheelchair_core/pose2d.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace wheelchair_controller {

constexpr double kMinPathLength = 0.01;  ///< [m] shorter paths are "zero-length"

/// The smoothed path the controller tracks for `path` (base_link poses in map), or null with
/// the reason the controller refuses it (empty, non-finite, zero-length).
std::shared_ptr<const SmoothPath> drivenPath(const std::vector<Pose2D>& path,
                                             std::string& rejection);

/// True if a chair at rest with heading `yaw` first rotates in place to the path's tangent.
bool rotatesBeforePath(const SmoothPath& path, double yaw, const TrackerConfig& config);
/// True if the chair rotates in place to the goal heading at the end of the path.
bool rotatesToGoalHeading(const SmoothPath& path, const TrackerConfig& config);

/// One pose of the motion and the phase it belongs to.
struct SweepPose {
  enum class Phase { kStartRotation, kPath, kGoalRotation };
  Pose2D pose;
  Phase phase = Phase::kPath;
};

/// How finely the motion is sampled.
struct SweepSampling {
  double max_step = 0.02;                ///< [m] between poses along the path
  double max_turn = 2.0 * M_PI / 180.0;  ///< [rad] between poses
};

/// Poses of base_link when the controller drives `path` from `start` (the chair's pose, yaw
/// included): the rotation from the start yaw to the smoothed path's tangent (at rest the
/// controller rotates in place when off by more than start_heading_tolerance; below it the chair
/// turns while it drives off, sweeping about the same poses: included either way), the smoothed
/// path with its tangent heading (the controller keeps the axle on it, off-tracking
/// compensated), and the rotation to the goal heading when rotatesToGoalHeading(). Empty if the
/// controller would refuse the path.
std::vector<SweepPose> executedSweep(const Pose2D& start, const std::vector<Pose2D>& path,
                                     const TrackerConfig& config = TrackerConfig(),
                                     const SweepSampling& sampling = SweepSampling());

/// Poses of an in-place rotation about (x, y) from yaw0 to yaw1 the short way, at most
/// `max_turn` apart, both ends included.
std::vector<Pose2D> rotationInPlace(double x, double y, double yaw0, double yaw1, double max_turn);

}  // namespace wheelchair_controller
