// Generated grids for the planners' tests and benchmark (test support, not part of any planner):
// seeded perfect mazes and straight corridors.
#pragma once

#include <wheelchair_core/occupancy_map.h>

#include <cstdint>

namespace wheelchair_planner {

/// A perfect maze (depth-first backtracker, seeded) on a size x size grid: passages
/// `corridor_cells` wide between walls `wall_cells` thick, closed by an outer wall. Passage
/// (i, j) of the maze has its lower-left free cell at (wall + i * pitch, wall + j * pitch) with
/// pitch = corridor + wall.
wheelchair_core::OccupancyMap makeMaze(int size, int corridor_cells, int wall_cells, uint32_t seed,
                                       double resolution = 0.05);

/// Centre of maze passage (i, j) in world coordinates.
void mazePassageCentre(int i, int j, int corridor_cells, int wall_cells, double resolution,
                       double& x, double& y);

/// A straight corridor along x: `length` by `width` metres of free space inside a wall of
/// `wall_cells` on every side; origin at the lower-left corner of the grid.
wheelchair_core::OccupancyMap makeCorridor(double length, double width, double resolution,
                                           int wall_cells = 2);

}  // namespace wheelchair_planner
