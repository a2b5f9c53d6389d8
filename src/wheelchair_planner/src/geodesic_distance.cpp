#include "geodesic_distance.h"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace wheelchair_planner {

std::vector<double> geodesicToGoal(const ConfigSpace& cs, double axle_radius, int gx, int gy) {
  const int w = cs.width(), h = cs.height();
  std::vector<double> dist(static_cast<size_t>(w) * h, std::numeric_limits<double>::infinity());
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[cs.index(gx, gy)] = 0.0;
  open.push({0.0, cs.index(gx, gy)});
  const double res = cs.resolution();
  while (!open.empty()) {
    const auto [d, k] = open.top();
    open.pop();
    if (d > dist[k]) continue;
    const int ix = static_cast<int>(k % w), iy = static_cast<int>(k / w);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = ix + dx, ny = iy + dy;
        if ((dx == 0 && dy == 0) || !cs.inBounds(nx, ny)) continue;
        if (cs.obstacleDistance(nx, ny) < axle_radius) continue;
        const double nd = d + res * ((dx != 0 && dy != 0) ? M_SQRT2 : 1.0);
        const size_t nk = cs.index(nx, ny);
        if (nd < dist[nk]) {
          dist[nk] = nd;
          open.push({nd, nk});
        }
      }
    }
  }
  return dist;
}

}  // namespace wheelchair_planner
