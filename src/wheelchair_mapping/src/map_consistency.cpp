#include <wheelchair_mapping/map_consistency.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_mapping {

void addEndpoints(const wheelchair_core::OccupancyMap& map,
                  const wheelchair_core::LaserScan2D& scan, const wheelchair_core::Pose2D& pose,
                  double max_range, EndpointConsistency& tally) {
  const double limit = std::min(scan.range_max, max_range);
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const double r = scan.ranges[i];
    if (!std::isfinite(r) || r < scan.range_min || r > limit) continue;
    ++tally.endpoints;
    const double a = pose.yaw + scan.angle_min + i * scan.angle_increment;
    int ix, iy;
    if (!map.worldToCell(pose.x + r * std::cos(a), pose.y + r * std::sin(a), ix, iy)) continue;
    if (map.at(ix, iy) == wheelchair_core::kOccupied) ++tally.on_occupied;
    bool near = false;
    for (int dy = -1; dy <= 1 && !near; ++dy) {
      for (int dx = -1; dx <= 1 && !near; ++dx) {
        near = map.inBounds(ix + dx, iy + dy) &&
               map.at(ix + dx, iy + dy) == wheelchair_core::kOccupied;
      }
    }
    if (near) ++tally.near_occupied;
  }
}

}  // namespace wheelchair_mapping
