// Which way the chair moves along a plan. A plan pose's yaw is the chair's heading there (the
// base_link yaw, not the direction of motion), so a piece whose poses face against their motion
// is driven in reverse (the convention of Nav2's Smac planners). Planner, controller and safety
// supervisor share this one rule; a plan of tangent headings (every forward planner) is one
// forward piece.
#pragma once

#include <wheelchair_core/pose2d.h>

#include <cstddef>
#include <vector>

namespace wheelchair_core {

enum class Direction { kForward, kReverse };

/// A maximal run of the plan driven one way: poses [begin, end] (end included; the next piece
/// begins at this end pose, the cusp where the chair stops and changes direction).
struct PathPiece {
  size_t begin = 0;
  size_t end = 0;
  Direction direction = Direction::kForward;
};

/// The direction of the step from `from` to `to`: reverse if the chair's heading at `from` points
/// against the step (more than 120 degrees off), forward if within 60 degrees; a step sideways
/// or too short to tell (< 0.1 mm) keeps `previous`.
Direction stepDirection(const Pose2D& from, const Pose2D& to, Direction previous);

/// The plan split where its direction changes (cusps). One piece for a forward plan; empty for
/// fewer than two poses. The first step that can tell decides the first piece's direction.
std::vector<PathPiece> splitAtCusps(const std::vector<Pose2D>& path);

/// Metres driven in reverse along the plan (sum of its reverse pieces' polyline lengths).
double reversedLength(const std::vector<Pose2D>& path);

/// The number of cusps (direction changes) of the plan.
inline size_t cuspCount(const std::vector<Pose2D>& path) {
  const size_t pieces = splitAtCusps(path).size();
  return pieces > 0 ? pieces - 1 : 0;
}

}  // namespace wheelchair_core
