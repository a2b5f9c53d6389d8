#include "grid_measures.h"

#include <algorithm>
#include <cmath>
#include <deque>

namespace wheelchair_test {
namespace {

/// Distance [cells] between a cell centre and the nearest point of a cell (dx, dy) away.
double boxDistanceCells(int dx, int dy) {
  const double ex = std::max(std::abs(dx) - 0.5, 0.0);
  const double ey = std::max(std::abs(dy) - 0.5, 0.0);
  return std::hypot(ex, ey);
}

}  // namespace

double clearanceAt(const Grid& grid, double x, double y, double max_radius) {
  const int reach = static_cast<int>(std::ceil(max_radius / grid.resolution)) + 1;
  const int cx = grid.cellX(x), cy = grid.cellY(y);
  double best = max_radius;
  for (int iy = cy - reach; iy <= cy + reach; ++iy) {
    for (int ix = cx - reach; ix <= cx + reach; ++ix) {
      if (!grid.occupied(ix, iy)) continue;
      const double x0 = grid.origin_x + ix * grid.resolution, x1 = x0 + grid.resolution;
      const double y0 = grid.origin_y + iy * grid.resolution, y1 = y0 + grid.resolution;
      const double dx = std::max({x0 - x, 0.0, x - x1});
      const double dy = std::max({y0 - y, 0.0, y - y1});
      best = std::min(best, std::hypot(dx, dy));
    }
  }
  return best;
}

int freeRun(const Grid& grid, int ix, int iy, char axis, bool* bounded) {
  if (!grid.free(ix, iy)) return 0;
  const int sx = axis == 'x' ? 1 : 0, sy = axis == 'y' ? 1 : 0;
  int lo = 0, hi = 0;
  while (grid.free(ix - (lo + 1) * sx, iy - (lo + 1) * sy)) ++lo;
  while (grid.free(ix + (hi + 1) * sx, iy + (hi + 1) * sy)) ++hi;
  if (bounded) {
    *bounded = grid.occupied(ix - (lo + 1) * sx, iy - (lo + 1) * sy) &&
               grid.occupied(ix + (hi + 1) * sx, iy + (hi + 1) * sy);
  }
  return lo + hi + 1;
}

std::vector<bool> passableCells(const Grid& grid, double clearance) {
  std::vector<bool> passable(grid.cells.size());
  for (size_t i = 0; i < passable.size(); ++i) passable[i] = grid.cells[i] == Cell::kFree;
  const double r = clearance / grid.resolution;
  const int reach = static_cast<int>(std::ceil(r)) + 1;
  std::vector<std::pair<int, int>> stamp;
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      if (boxDistanceCells(dx, dy) < r) stamp.emplace_back(dx, dy);
    }
  }
  for (int iy = 0; iy < grid.height; ++iy) {
    for (int ix = 0; ix < grid.width; ++ix) {
      if (grid.at(ix, iy) != Cell::kOccupied) continue;
      for (const auto& [dx, dy] : stamp) {
        if (grid.inBounds(ix + dx, iy + dy)) {
          passable[static_cast<size_t>(iy + dy) * grid.width + ix + dx] = false;
        }
      }
    }
  }
  return passable;
}

std::vector<bool> reachableFrom(const Grid& grid, const std::vector<bool>& passable, int ix,
                                int iy) {
  std::vector<bool> seen(grid.cells.size(), false);
  const auto index = [&](int x, int y) { return static_cast<size_t>(y) * grid.width + x; };
  if (!grid.inBounds(ix, iy) || !passable[index(ix, iy)]) return seen;
  std::deque<std::pair<int, int>> queue{{ix, iy}};
  seen[index(ix, iy)] = true;
  while (!queue.empty()) {
    const auto [x, y] = queue.front();
    queue.pop_front();
    for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
      const int nx = x + dx, ny = y + dy;
      if (grid.inBounds(nx, ny) && passable[index(nx, ny)] && !seen[index(nx, ny)]) {
        seen[index(nx, ny)] = true;
        queue.emplace_back(nx, ny);
      }
    }
  }
  return seen;
}

int thinOccupiedCells(const Grid& grid) {
  const auto solid_block = [&](int x, int y) {  // 2 x 2 block with lower-left cell (x, y)
    return grid.occupied(x, y) && grid.occupied(x + 1, y) && grid.occupied(x, y + 1) &&
           grid.occupied(x + 1, y + 1);
  };
  int thin = 0;
  for (int iy = 0; iy < grid.height; ++iy) {
    for (int ix = 0; ix < grid.width; ++ix) {
      if (grid.at(ix, iy) == Cell::kOccupied && !solid_block(ix, iy) && !solid_block(ix - 1, iy) &&
          !solid_block(ix, iy - 1) && !solid_block(ix - 1, iy - 1)) {
        ++thin;
      }
    }
  }
  return thin;
}

double longestFreeBandAlongX(const Grid& grid, double band_width) {
  const int band = static_cast<int>(std::lround(band_width / grid.resolution));
  int best = 0;
  for (int y0 = 0; y0 + band <= grid.height; ++y0) {
    int run = 0;
    for (int ix = 0; ix < grid.width; ++ix) {
      bool column_free = true;
      for (int iy = y0; iy < y0 + band && column_free; ++iy) column_free = grid.free(ix, iy);
      run = column_free ? run + 1 : 0;
      best = std::max(best, run);
    }
  }
  return best * grid.resolution;
}

}  // namespace wheelchair_test
