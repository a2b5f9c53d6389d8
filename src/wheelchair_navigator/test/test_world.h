// A small test world for the navigator's core tests: a 10 m x 6 m grid at 5 cm, free inside
// x 0.1-9.9, y 0.1-5.0, with a 1 m x 1 m block (furniture) at x 7-8, y 1-2 and a pocket 0.4 m
// wide and 0.9 m deep in the top wall at x 2.0-2.4 (narrower than the chair); the chair's
// footprint (0.62 m wide, 0.30 m ahead of and 0.80 m behind the axle, like chair.yaml).
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_core/pose2d.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace wheelchair_navigator_test {

inline wheelchair_core::OccupancyMap testRoom() {
  wheelchair_core::OccupancyMap map;
  map.resolution = 0.05;
  map.width = 200;
  map.height = 120;
  map.data.assign(static_cast<size_t>(map.width) * map.height, wheelchair_core::kFree);
  for (int iy = 0; iy < map.height; ++iy) {
    for (int ix = 0; ix < map.width; ++ix) {
      double x, y;
      map.cellToWorld(ix, iy, x, y);
      const bool pocket = x > 2.0 && x < 2.4 && y < 5.9;
      const bool wall = x < 0.1 || y < 0.1 || x > 9.9 || (y > 5.0 && !pocket);
      const bool block = x > 7.0 && x < 8.0 && y > 1.0 && y < 2.0;
      if (wall || block) map.at(ix, iy) = wheelchair_core::kOccupied;
    }
  }
  return map;
}

inline wheelchair_core::Polygon chairFootprint() {
  return {{0.30, -0.31}, {0.30, 0.31}, {-0.80, 0.31}, {-0.80, -0.31}};
}

constexpr double kHalfWidth = 0.31;

/// A straight route from `a` to `b`, a pose every 5 cm, heading along it.
inline std::vector<wheelchair_core::Pose2D> straight(double ax, double ay, double bx, double by) {
  std::vector<wheelchair_core::Pose2D> out;
  const double length = std::hypot(bx - ax, by - ay);
  const double yaw = std::atan2(by - ay, bx - ax);
  const int n = std::max(1, static_cast<int>(std::ceil(length / 0.05)));
  for (int i = 0; i <= n; ++i) out.push_back({ax + (bx - ax) * i / n, ay + (by - ay) * i / n, yaw});
  return out;
}

}  // namespace wheelchair_navigator_test
