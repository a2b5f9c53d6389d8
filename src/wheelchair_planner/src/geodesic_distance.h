// The footprint search's heuristic field (internal header of footprint_search.cpp).
#pragma once

#include <wheelchair_planner/config_space.h>

#include <vector>

namespace wheelchair_planner {

/// 8-connected Dijkstra distance [m] from every cell to the goal cell over the cells whose
/// obstacle distance is at least `axle_radius` (where the chair's axle may be); +infinity where
/// the goal cannot be reached. A lower bound of the path length.
std::vector<double> geodesicToGoal(const ConfigSpace& cs, double axle_radius, int gx, int gy);

/// The narrowest passage on the widest way from cell (sx, sy) to cell (gx, gy): the route whose
/// smallest clear width is largest (a bottleneck path over 8-connected free cells), that width
/// [m, to cell accuracy: twice the obstacle distance plus a cell] and where it is (x, y). 0 if
/// the cells are not connected at all.
double narrowestPassage(const ConfigSpace& cs, int sx, int sy, int gx, int gy, double& x,
                        double& y);

}  // namespace wheelchair_planner
