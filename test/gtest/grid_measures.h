// Measurements on a world's grid: clearance, free runs (door and corridor widths), reachability
// for a chair of a given half-width, wall thickness.
#pragma once

#include "world_files.h"

#include <vector>

namespace wheelchair_test {

/// Distance [m] from (x, y) to the nearest point of an occupied cell, searched up to
/// `max_radius` (returned when nothing is nearer).
double clearanceAt(const Grid& grid, double x, double y, double max_radius);

/// Number of contiguous free cells along `axis` ('x' or 'y') through cell (ix, iy); 0 if that
/// cell is not free. `bounded` tells whether both ends stop at an occupied cell.
int freeRun(const Grid& grid, int ix, int iy, char axis, bool* bounded = nullptr);

/// Cells a disc of radius `clearance` [m] centred on the cell centre fits in without touching
/// an occupied cell (index iy * width + ix).
std::vector<bool> passableCells(const Grid& grid, double clearance);

/// Cells reachable from (ix, iy) through 4-connected cells of `passable`.
std::vector<bool> reachableFrom(const Grid& grid, const std::vector<bool>& passable, int ix,
                                int iy);

/// Occupied cells that are not part of any 2 x 2 block of occupied cells (walls or furniture
/// thinner than two cells).
int thinOccupiedCells(const Grid& grid);

/// Length [m] of the longest straight stretch along x over which a band `band_width` [m] high
/// is entirely free (the longest corridor-like passage of that width).
double longestFreeBandAlongX(const Grid& grid, double band_width);

}  // namespace wheelchair_test
