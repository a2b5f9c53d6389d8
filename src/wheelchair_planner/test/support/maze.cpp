#include <wheelchair_planner_test/maze.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace wheelchair_planner {

using wheelchair_core::OccupancyMap;

namespace {

OccupancyMap blankMap(int width, int height, double resolution, int8_t value) {
  OccupancyMap m;
  m.resolution = resolution;
  m.width = width;
  m.height = height;
  m.data.assign(static_cast<size_t>(width) * height, value);
  return m;
}

void fill(OccupancyMap& m, int x0, int y0, int w, int h, int8_t value) {
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) m.at(x, y) = value;
}

}  // namespace

OccupancyMap makeMaze(int size, int corridor, int wall, uint32_t seed, double resolution) {
  const int pitch = corridor + wall;
  const int n = (size - wall) / pitch;
  if (n < 1) throw std::invalid_argument("makeMaze: grid too small for one passage");
  OccupancyMap m = blankMap(size, size, resolution, wheelchair_core::kOccupied);
  std::mt19937 rng(seed);
  std::vector<uint8_t> visited(static_cast<size_t>(n) * n, 0);
  std::vector<int> stack{0};
  visited[0] = 1;
  fill(m, wall, wall, corridor, corridor, wheelchair_core::kFree);
  while (!stack.empty()) {
    const int c = stack.back();
    const int ci = c % n, cj = c / n;
    std::vector<int> options;
    const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
    for (int d = 0; d < 4; ++d) {
      const int ni = ci + di[d], nj = cj + dj[d];
      if (ni >= 0 && nj >= 0 && ni < n && nj < n && !visited[nj * n + ni]) options.push_back(d);
    }
    if (options.empty()) {
      stack.pop_back();
      continue;
    }
    const int d = options[std::uniform_int_distribution<size_t>(0, options.size() - 1)(rng)];
    const int ni = ci + di[d], nj = cj + dj[d];
    visited[nj * n + ni] = 1;
    stack.push_back(nj * n + ni);
    // Open the passage cell and the wall between the two passages.
    fill(m, wall + ni * pitch, wall + nj * pitch, corridor, corridor, wheelchair_core::kFree);
    const int x0 = wall + std::min(ci, ni) * pitch, y0 = wall + std::min(cj, nj) * pitch;
    fill(m, x0, y0, di[d] != 0 ? corridor + pitch : corridor,
         dj[d] != 0 ? corridor + pitch : corridor, wheelchair_core::kFree);
  }
  return m;
}

void mazePassageCentre(int i, int j, int corridor, int wall, double resolution, double& x,
                       double& y) {
  const int pitch = corridor + wall;
  x = (wall + i * pitch + 0.5 * corridor) * resolution;
  y = (wall + j * pitch + 0.5 * corridor) * resolution;
}

OccupancyMap makeCorridor(double length, double width, double resolution, int wall) {
  const int lx = static_cast<int>(std::lround(length / resolution));
  const int ly = static_cast<int>(std::lround(width / resolution));
  OccupancyMap m = blankMap(lx + 2 * wall, ly + 2 * wall, resolution, wheelchair_core::kOccupied);
  fill(m, wall, wall, lx, ly, wheelchair_core::kFree);
  return m;
}

}  // namespace wheelchair_planner
