#include "geodesic_distance.h"

#include <algorithm>
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

double narrowestPassage(const ConfigSpace& cs, int sx, int sy, int gx, int gy, double& x,
                        double& y) {
  const int w = cs.width(), h = cs.height();
  const size_t n = static_cast<size_t>(w) * h;
  // Widest path: grow from the start, always from the cell with the largest bottleneck so far.
  std::vector<double> best(n, -1.0);
  std::vector<size_t> parent(n, n);
  std::priority_queue<std::pair<double, size_t>> open;
  const size_t s = cs.index(sx, sy), g = cs.index(gx, gy);
  best[s] = cs.obstacleDistance(sx, sy);
  open.push({best[s], s});
  while (!open.empty()) {
    const auto [b, k] = open.top();
    open.pop();
    if (b < best[k]) continue;
    if (k == g) break;
    const int ix = static_cast<int>(k % w), iy = static_cast<int>(k / w);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = ix + dx, ny = iy + dy;
        if ((dx == 0 && dy == 0) || !cs.inBounds(nx, ny) || cs.obstacleDistance(nx, ny) <= 0.0)
          continue;
        const size_t nk = cs.index(nx, ny);
        const double nb = std::min(b, static_cast<double>(cs.obstacleDistance(nx, ny)));
        if (nb > best[nk]) {
          best[nk] = nb;
          parent[nk] = k;
          open.push({nb, nk});
        }
      }
    }
  }
  if (best[g] <= 0.0) return 0.0;
  // Where the bottleneck is: the cell on the route with the smallest obstacle distance.
  size_t at = g;
  for (size_t k = g; k != n; k = parent[k])
    if (cs.obstacleDistance(k % w, k / w) < cs.obstacleDistance(at % w, at / w)) at = k;
  cs.gridToWorld(static_cast<double>(at % w), static_cast<double>(at / w), x, y);
  return 2.0 * best[g] + cs.resolution();
}

}  // namespace wheelchair_planner
