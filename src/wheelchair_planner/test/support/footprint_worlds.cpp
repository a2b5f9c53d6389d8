#include <wheelchair_controller/smooth_path.h>
#include <wheelchair_core/path_direction.h>
#include <wheelchair_planner_test/footprint_worlds.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_planner {

using wheelchair_core::OccupancyMap;
using wheelchair_core::Pose2D;

namespace {

/// Signed distance from a map point to the chair's box at `pose` (exact box SDF).
double boxDistance(const Pose2D& pose, double x, double y) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const double u = c * (x - pose.x) + s * (y - pose.y), v = -s * (x - pose.x) + c * (y - pose.y);
  const double qx = std::abs(u - (-0.25)) - 0.55, qy = std::abs(v) - 0.31;
  return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
}

}  // namespace

const wheelchair_core::Polygon& chairBox() {
  static const wheelchair_core::Polygon box{
      {0.30, 0.31}, {-0.80, 0.31}, {-0.80, -0.31}, {0.30, -0.31}};
  return box;
}

PlannerSettings chairBoxSettings() {
  PlannerSettings settings;
  settings.footprint = chairBox();
  settings.cspace.inscribed_radius = 0.31;
  return settings;
}

OccupancyMap carved(double size, const std::vector<std::array<double, 4>>& free_boxes) {
  OccupancyMap map;
  map.resolution = 0.05;
  map.width = map.height = static_cast<int>(std::lround(size / map.resolution));
  map.data.assign(static_cast<size_t>(map.width) * map.height, wheelchair_core::kOccupied);
  for (int iy = 0; iy < map.height; ++iy) {
    for (int ix = 0; ix < map.width; ++ix) {
      double x, y;
      map.cellToWorld(ix, iy, x, y);
      for (const auto& b : free_boxes)
        if (x > b[0] && x < b[1] && y > b[2] && y < b[3]) map.at(ix, iy) = wheelchair_core::kFree;
    }
  }
  return map;
}

OccupancyMap lCorner(double w) {
  return carved(7.0, {{0.5, 6.5, 0.5, 0.5 + w}, {6.5 - w, 6.5, 0.5, 6.5}});
}

double bruteClearance(const OccupancyMap& map, const Pose2D& pose) {
  double best = 1e9;
  int cx, cy;
  map.worldToCell(pose.x, pose.y, cx, cy);
  const int reach = static_cast<int>(1.2 / map.resolution);
  for (int iy = cy - reach; iy <= cy + reach; ++iy) {
    for (int ix = cx - reach; ix <= cx + reach; ++ix) {
      if (map.inBounds(ix, iy) && map.at(ix, iy) < 50) continue;
      for (int a = 0; a <= 5; ++a) {
        for (int b = 0; b <= 5; ++b) {
          const double x = map.origin_x + (ix + a / 5.0) * map.resolution;
          const double y = map.origin_y + (iy + b / 5.0) * map.resolution;
          best = std::min(best, boxDistance(pose, x, y));
        }
      }
    }
  }
  return best;
}

double bruteSweepClearance(const OccupancyMap& map, const Pose2D& start,
                           const std::vector<Pose2D>& plan) {
  std::vector<Pose2D> body;
  const auto rotate = [&](double x, double y, double a0, double a1) {
    const double d = std::remainder(a1 - a0, 2.0 * M_PI);
    for (int k = 0; k <= 60; ++k) body.push_back({x, y, a0 + d * k / 60.0});
  };
  // Piece by piece (split at the cusps): a reverse piece faces against its tangent.
  Pose2D at = start;
  for (const wheelchair_core::PathPiece& piece : wheelchair_core::splitAtCusps(plan)) {
    const std::vector<Pose2D> poses(plan.begin() + piece.begin, plan.begin() + piece.end + 1);
    const wheelchair_controller::SmoothPath path(poses);
    const double flip = piece.direction == wheelchair_core::Direction::kReverse ? M_PI : 0.0;
    rotate(at.x, at.y, at.yaw, path.at(0.0).heading + flip);
    for (double s = 0.0; s <= path.length(); s += 0.01) {
      const auto q = path.at(s);
      body.push_back({q.position.x(), q.position.y(), q.heading + flip});
    }
    const auto end = path.at(path.length());
    at = {end.position.x(), end.position.y(), end.heading + flip};
  }
  rotate(at.x, at.y, at.yaw, plan.back().yaw);
  double best = 1e9;
  for (const Pose2D& p : body) best = std::min(best, bruteClearance(map, p));
  return best;
}

}  // namespace wheelchair_planner
