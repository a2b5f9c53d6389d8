// Test helper: a built map compared cell by cell with the ground-truth world. Of the cells the
// laser observed (not unknown), the fraction classified like the truth (occupied or not), the
// thickest wall away from the truth's junctions, and how far occupied cells spill off the walls.
#pragma once

#include <wheelchair_core/occupancy_map.h>

#include <algorithm>

namespace wheelchair_mapping::test {

struct Accuracy {
  int observed = 0;
  int correct = 0;
  int max_wall_run = 0;
  int max_spill = 0;  ///< [cells] farthest occupied cell from the truth's nearest occupied one
  double fraction() const { return observed ? static_cast<double>(correct) / observed : 0.0; }
};

inline int occupiedRun(const wheelchair_core::OccupancyMap& m, int x, int y, int dx, int dy) {
  auto occupied = [&m](int cx, int cy) {
    return m.inBounds(cx, cy) && m.at(cx, cy) == wheelchair_core::kOccupied;
  };
  int n = 1;
  for (int k = 1; occupied(x + k * dx, y + k * dy); ++k) ++n;
  for (int k = 1; occupied(x - k * dx, y - k * dy); ++k) ++n;
  return n;
}

// True where two walls of the ground truth meet (corners, T-junctions) or within 5 cells of
// it: there a wall has no single thickness.
inline bool nearJunction(const wheelchair_core::OccupancyMap& truth, int tx, int ty) {
  for (int y = ty - 5; y <= ty + 5; ++y) {
    for (int x = tx - 5; x <= tx + 5; ++x) {
      if (truth.inBounds(x, y) && truth.at(x, y) == wheelchair_core::kOccupied &&
          std::min(occupiedRun(truth, x, y, 1, 0), occupiedRun(truth, x, y, 0, 1)) > 2) {
        return true;
      }
    }
  }
  return false;
}

// Calls visit(x, y, in_truth, tx, ty) for every occupied cell (x, y) of the built map, with the
// truth's cell at the same place (in_truth false: the place is outside the truth).
template <typename Visit>
void forEachOccupied(const wheelchair_core::OccupancyMap& built,
                     const wheelchair_core::OccupancyMap& truth, Visit&& visit) {
  for (int y = 0; y < built.height; ++y) {
    for (int x = 0; x < built.width; ++x) {
      if (built.at(x, y) != wheelchair_core::kOccupied) continue;
      double wx, wy;
      int tx = -1, ty = -1;
      built.cellToWorld(x, y, wx, wy);
      const bool in_truth = truth.worldToCell(wx, wy, tx, ty);
      visit(x, y, in_truth, tx, ty);
    }
  }
}

// Wall thickness at an occupied cell away from junctions: the shorter of its horizontal and
// vertical runs of occupied cells (the run across the wall it stands in).
inline int maxWallThickness(const wheelchair_core::OccupancyMap& built,
                            const wheelchair_core::OccupancyMap& truth) {
  int worst = 0;
  forEachOccupied(built, truth, [&](int x, int y, bool in_truth, int tx, int ty) {
    if (in_truth && nearJunction(truth, tx, ty)) return;
    worst =
        std::max(worst, std::min(occupiedRun(built, x, y, 1, 0), occupiedRun(built, x, y, 0, 1)));
  });
  return worst;
}

// Chebyshev distance [cells] from truth cell (tx, ty) to the nearest occupied truth cell, at
// most `cap` (also when there is none within it).
inline int distanceToWall(const wheelchair_core::OccupancyMap& truth, int tx, int ty, int cap) {
  for (int d = 0; d < cap; ++d) {
    for (int y = ty - d; y <= ty + d; ++y) {
      for (int x = tx - d; x <= tx + d; ++x) {
        if (truth.inBounds(x, y) && truth.at(x, y) == wheelchair_core::kOccupied) return d;
      }
    }
  }
  return cap;
}

// The farthest any occupied cell of the built map lies from a wall of the truth [cells]: what
// range noise and pose errors put in front of (or behind) the walls. Outside the truth: `cap`.
inline int maxSpill(const wheelchair_core::OccupancyMap& built,
                    const wheelchair_core::OccupancyMap& truth, int cap = 10) {
  int worst = 0;
  forEachOccupied(built, truth, [&](int, int, bool in_truth, int tx, int ty) {
    worst = std::max(worst, in_truth ? distanceToWall(truth, tx, ty, cap) : cap);
  });
  return worst;
}

inline Accuracy compare(const wheelchair_core::OccupancyMap& built,
                        const wheelchair_core::OccupancyMap& truth) {
  Accuracy a;
  for (int iy = 0; iy < built.height; ++iy) {
    for (int ix = 0; ix < built.width; ++ix) {
      const int8_t v = built.at(ix, iy);
      if (v == wheelchair_core::kUnknown) continue;
      double x, y;
      int tx, ty;
      built.cellToWorld(ix, iy, x, y);
      if (!truth.worldToCell(x, y, tx, ty)) {
        ++a.observed;  // observed outside the world: wrong by definition
        continue;
      }
      ++a.observed;
      a.correct +=
          ((v == wheelchair_core::kOccupied) == (truth.at(tx, ty) == wheelchair_core::kOccupied))
              ? 1
              : 0;
    }
  }
  a.max_wall_run = maxWallThickness(built, truth);
  a.max_spill = maxSpill(built, truth);
  return a;
}

}  // namespace wheelchair_mapping::test
