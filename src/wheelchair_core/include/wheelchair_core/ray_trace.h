// The grid cells along a straight segment: every cell it crosses (Amanatides & Woo voxel
// traversal), or one cell per step of the digital line between two cells (Bresenham).
#pragma once

#include <cmath>
#include <cstdlib>
#include <limits>

namespace wheelchair_core {

/// Calls visit(ix, iy, is_last) for every cell crossed from (gx0, gy0) to (gx1, gy1), both
/// given in cell units (cell (i, j) spans [i, i+1) x [j, j+1)); the last call is the end cell.
template <typename Visit>
void traceCells(double gx0, double gy0, double gx1, double gy1, Visit&& visit) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int ix = static_cast<int>(std::floor(gx0));
  int iy = static_cast<int>(std::floor(gy0));
  const int ex = static_cast<int>(std::floor(gx1));
  const int ey = static_cast<int>(std::floor(gy1));
  const double dx = gx1 - gx0;
  const double dy = gy1 - gy0;
  const int step_x = dx > 0 ? 1 : -1;
  const int step_y = dy > 0 ? 1 : -1;
  const double delta_x = dx != 0 ? 1.0 / std::abs(dx) : kInf;
  const double delta_y = dy != 0 ? 1.0 / std::abs(dy) : kInf;
  double t_x = dx > 0 ? (ix + 1 - gx0) * delta_x : (dx < 0 ? (gx0 - ix) * delta_x : kInf);
  double t_y = dy > 0 ? (iy + 1 - gy0) * delta_y : (dy < 0 ? (gy0 - iy) * delta_y : kInf);
  for (int n = std::abs(ex - ix) + std::abs(ey - iy); n > 0; --n) {
    visit(ix, iy, false);
    // Never step past the end cell on one axis (guards against rounding at cell corners).
    if (iy == ey || (ix != ex && t_x < t_y)) {
      t_x += delta_x;
      ix += step_x;
    } else {
      t_y += delta_y;
      iy += step_y;
    }
  }
  visit(ix, iy, true);
}

/// Calls visit(ix, iy, is_last) for the cells of the 8-connected digital line (Bresenham) from
/// cell (ix0, iy0) to cell (ix1, iy1): one cell per step along the major axis,
/// max(|dx|, |dy|) + 1 cells, the last call the end cell. Unlike traceCells it skips the cells
/// the segment only clips at a corner (a laser beam marks one cell per cell of travel, as in
/// MRPT's and gmapping's grids).
template <typename Visit>
void traceLineCells(int ix0, int iy0, int ix1, int iy1, Visit&& visit) {
  const int dx = std::abs(ix1 - ix0), dy = -std::abs(iy1 - iy0);
  const int sx = ix0 < ix1 ? 1 : -1, sy = iy0 < iy1 ? 1 : -1;
  int err = dx + dy;
  for (int x = ix0, y = iy0;;) {
    const bool last = x == ix1 && y == iy1;
    visit(x, y, last);
    if (last) return;
    const int e2 = 2 * err;
    if (e2 >= dy) {
      err += dy;
      x += sx;
    }
    if (e2 <= dx) {
      err += dx;
      y += sy;
    }
  }
}

}  // namespace wheelchair_core
