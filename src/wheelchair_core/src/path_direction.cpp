#include <wheelchair_core/path_direction.h>

#include <cmath>

namespace wheelchair_core {

namespace {
constexpr double kMinStep = 1e-4;  // [m] shorter steps cannot tell a direction
constexpr double kForwardCos =
    0.5;  // within 60 degrees of the heading: forward; beyond 120: reverse
}  // namespace

Direction stepDirection(const Pose2D& from, const Pose2D& to, Direction previous) {
  const double dx = to.x - from.x, dy = to.y - from.y;
  const double length = std::hypot(dx, dy);
  if (!(length >= kMinStep)) return previous;
  const double c = (std::cos(from.yaw) * dx + std::sin(from.yaw) * dy) / length;
  if (c > kForwardCos) return Direction::kForward;
  if (c < -kForwardCos) return Direction::kReverse;
  return previous;
}

std::vector<PathPiece> splitAtCusps(const std::vector<Pose2D>& path) {
  std::vector<PathPiece> pieces;
  if (path.size() < 2) return pieces;
  // The first step that tells a direction decides the first piece (a plan may start with
  // repeated poses).
  Direction first = Direction::kForward;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const double dx = path[i + 1].x - path[i].x, dy = path[i + 1].y - path[i].y;
    if (std::hypot(dx, dy) < kMinStep) continue;
    first = stepDirection(path[i], path[i + 1], Direction::kForward);
    break;
  }
  PathPiece current{0, 0, first};
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Direction d = stepDirection(path[i], path[i + 1], current.direction);
    if (d != current.direction) {
      current.end = i;
      pieces.push_back(current);
      current = PathPiece{i, i, d};
    }
  }
  current.end = path.size() - 1;
  pieces.push_back(current);
  return pieces;
}

double reversedLength(const std::vector<Pose2D>& path) {
  double length = 0.0;
  for (const PathPiece& piece : splitAtCusps(path)) {
    if (piece.direction != Direction::kReverse) continue;
    for (size_t i = piece.begin; i < piece.end; ++i)
      length += std::hypot(path[i + 1].x - path[i].x, path[i + 1].y - path[i].y);
  }
  return length;
}

}  // namespace wheelchair_core
