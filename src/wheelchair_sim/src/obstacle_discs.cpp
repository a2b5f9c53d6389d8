#include <wheelchair_core/polygon.h>
#include <wheelchair_sim/obstacle_discs.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace wheelchair_sim {

void ObstacleDiscs::add(const Disc& disc) {
  if (!disc.centre.allFinite() || !std::isfinite(disc.appear_time) || !(disc.radius > 0.0) ||
      !std::isfinite(disc.radius))
    throw std::invalid_argument("obstacle disc: need a finite centre and time and radius > 0");
  if (!disc.velocity.allFinite() || std::isnan(disc.vanish_time) ||
      !(disc.vanish_time > disc.appear_time))
    throw std::invalid_argument(
        "obstacle disc: need a finite velocity and a vanish time after the appear time");
  discs_.push_back(disc);
}

std::vector<Disc> ObstacleDiscs::presentAt(double now) const {
  std::vector<Disc> out;
  for (const Disc& d : discs_) {
    if (now < d.appear_time || now >= d.vanish_time) continue;
    out.push_back(d);
    out.back().centre += d.velocity * (now - d.appear_time);
  }
  return out;
}

double rayToDiscs(const Eigen::Vector2d& origin, double angle, const std::vector<Disc>& discs) {
  const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
  double best = std::numeric_limits<double>::infinity();
  for (const Disc& d : discs) {
    // |origin + t dir - c|^2 = r^2  ->  t^2 + 2 b t + k = 0
    const Eigen::Vector2d m = origin - d.centre;
    const double b = m.dot(dir), k = m.squaredNorm() - d.radius * d.radius;
    if (k <= 0.0) return 0.0;  // inside
    const double disc = b * b - k;
    if (b > 0.0 || disc < 0.0) continue;  // pointing away, or missing
    best = std::min(best, -b - std::sqrt(disc));
  }
  return best;
}

bool polygonTouchesDiscs(const wheelchair_core::Polygon& outline, const std::vector<Disc>& discs) {
  for (const Disc& d : discs) {
    if (wheelchair_core::insidePolygon(outline, d.centre)) return true;
    if (wheelchair_core::distanceToBoundary(outline, d.centre) <= d.radius) return true;
  }
  return false;
}

}  // namespace wheelchair_sim
