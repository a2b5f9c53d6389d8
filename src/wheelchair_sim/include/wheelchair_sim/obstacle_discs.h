// Obstacles that are not in the map: discs (a person is a 0.3 m disc) that appear at a given
// simulated time, may walk at a constant velocity and may vanish again. The laser sees them
// and the chair collides with them, like map cells.
#pragma once

#include <wheelchair_core/polygon.h>

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace wheelchair_sim {

struct Disc {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< [m] in the world (map) frame
  double radius = 0.15;                              ///< [m]
  double appear_time = 0.0;  ///< [s] of simulated time from which it is there
  /// [m/s] it walks from `centre` (where it is at appear_time) at this velocity
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  double vanish_time = INFINITY;  ///< [s] of simulated time from which it is gone
};

class ObstacleDiscs {
 public:
  /// Throws std::invalid_argument for a non-finite centre, velocity or appear time, radius <= 0,
  /// or a vanish time not after the appear time.
  void add(const Disc& disc);
  void clear() { discs_.clear(); }
  const std::vector<Disc>& all() const { return discs_; }
  /// The discs present at simulated time `now` (appeared, not vanished), each where it has
  /// walked to by then.
  std::vector<Disc> presentAt(double now) const;

 private:
  std::vector<Disc> discs_;
};

/// Distance along the ray from `origin` in direction `angle` to the nearest disc boundary,
/// or +Inf when it misses them all (a ray starting inside a disc hits at 0).
double rayToDiscs(const Eigen::Vector2d& origin, double angle, const std::vector<Disc>& discs);

/// True if the polygon `outline` (world frame, closed) overlaps any disc: the disc's centre
/// inside the polygon, or an edge closer to the centre than the radius.
bool polygonTouchesDiscs(const wheelchair_core::Polygon& outline, const std::vector<Disc>& discs);

}  // namespace wheelchair_sim
