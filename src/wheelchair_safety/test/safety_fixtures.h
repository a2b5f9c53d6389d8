// Shared fixtures of the supervisor's gtests: a corridor map, a straight path along it, the
// returns of a person.
#pragma once

#include <wheelchair_core/occupancy_map.h>
#include <wheelchair_core/pose2d.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace wheelchair_safety_test {

/// A 10 m x 4 m free corridor (5 cm cells); `wall`: its wall at x = 9 m is in the map.
inline wheelchair_core::OccupancyMap corridorMap(bool wall = true) {
  wheelchair_core::OccupancyMap map;
  map.width = 200;
  map.height = 80;
  map.data.assign(map.width * map.height, wheelchair_core::kFree);
  if (wall)
    for (int y = 0; y < map.height; ++y) map.at(180, y) = wheelchair_core::kOccupied;
  return map;
}

/// y = 2 from x = 1 to `end`, vertices 5 cm apart.
inline std::vector<wheelchair_core::Pose2D> straightPath(double end = 8.5) {
  std::vector<wheelchair_core::Pose2D> path;
  for (double x = 1.0; x <= end; x += 0.05) path.push_back({x, 2.0, 0.0});
  return path;
}

/// A person: the arc of returns a laser looking along +x sees of a 0.15 m disc at (x, y).
inline std::vector<Eigen::Vector2d> personAt(double x, double y) {
  std::vector<Eigen::Vector2d> returns;
  for (double a = -1.0; a <= 1.0; a += 0.2)
    returns.emplace_back(x - 0.15 * std::cos(a), y + 0.15 * std::sin(a));
  return returns;
}

}  // namespace wheelchair_safety_test
