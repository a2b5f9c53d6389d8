#include <wheelchair_navigator/layer_cut.h>
#include <wheelchair_planner/config_space.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <vector>

namespace wheelchair_navigator {

namespace {

constexpr uint32_t kUnreached = std::numeric_limits<uint32_t>::max();

/// Breadth-first search over the cells where `open(k)` holds, from `from`: each reached cell's
/// parent (kUnreached if not reached; `from` is its own parent).
template <typename Open>
std::vector<uint32_t> flood(const wheelchair_planner::ConfigSpace& cspace, size_t from, Open open) {
  const int w = cspace.width(), h = cspace.height();
  std::vector<uint32_t> parent(static_cast<size_t>(w) * h, kUnreached);
  std::deque<size_t> queue{from};
  parent[from] = static_cast<uint32_t>(from);
  while (!queue.empty()) {
    const size_t k = queue.front();
    queue.pop_front();
    const int x = static_cast<int>(k % w), y = static_cast<int>(k / w);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if ((dx == 0 && dy == 0) || !cspace.isFree(nx, ny)) continue;
        const size_t n = cspace.index(nx, ny);
        if (parent[n] != kUnreached || !open(n)) continue;
        parent[n] = static_cast<uint32_t>(k);
        queue.push_back(n);
      }
    }
  }
  return parent;
}

bool occupied(int8_t value) { return value >= 50; }

}  // namespace

std::optional<Eigen::Vector2d> layerCut(const wheelchair_planner::ConfigSpace& cspace,
                                        const wheelchair_core::OccupancyMap& static_map,
                                        const wheelchair_core::OccupancyMap& layer,
                                        const wheelchair_core::Pose2D& start,
                                        const wheelchair_core::Pose2D& goal, double radius) {
  const int w = cspace.width(), h = cspace.height();
  const bool same_grid = layer.width == w && layer.height == h && static_map.width == w &&
                         static_map.height == h &&
                         layer.data.size() == static_cast<size_t>(w) * h &&
                         static_map.data.size() == layer.data.size() &&
                         std::abs(layer.resolution - cspace.resolution()) < 1e-9;
  int sx, sy, gx, gy;
  if (!same_grid || !cspace.worldToCell(start.x, start.y, sx, sy) ||
      !cspace.worldToCell(goal.x, goal.y, gx, gy) || !cspace.isFree(sx, sy) ||
      !cspace.isFree(gx, gy))
    return std::nullopt;
  const size_t from = cspace.index(sx, sy), to = cspace.index(gx, gy);
  const std::vector<uint32_t> on_map = flood(cspace, from, [](size_t) { return true; });
  if (on_map[to] == kUnreached) return std::nullopt;  // no way there on the map itself

  // The cells the layer's obstacles block for the chair's centre.
  std::vector<uint8_t> blocked(on_map.size(), 0);
  const int reach = static_cast<int>(std::ceil(radius / cspace.resolution()));
  const double reach2 = std::pow(radius / cspace.resolution(), 2);
  bool any = false;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t k = cspace.index(x, y);
      if (!occupied(layer.data[k]) || occupied(static_map.data[k])) continue;
      any = true;
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx)
          if (dx * dx + dy * dy <= reach2 && cspace.inBounds(x + dx, y + dy))
            blocked[cspace.index(x + dx, y + dy)] = 1;
    }
  }
  if (!any) return std::nullopt;
  if (blocked[from]) return Eigen::Vector2d(start.x, start.y);  // right beside the chair
  const std::vector<uint32_t> with_layer =
      flood(cspace, from, [&](size_t k) { return blocked[k] == 0; });
  if (with_layer[to] != kUnreached) return std::nullopt;  // still open: not the layer's doing

  // Along the map's shortest connection (from the goal back), the blocked cell nearest the start.
  std::optional<size_t> cut;
  for (size_t k = to; k != from; k = on_map[k])
    if (blocked[k]) cut = k;
  if (!cut) return std::nullopt;
  double x, y;
  cspace.gridToWorld(static_cast<double>(*cut % w), static_cast<double>(*cut / w), x, y);
  return Eigen::Vector2d(x, y);
}

}  // namespace wheelchair_navigator
