// The footprint search's heuristic field (internal header of footprint_search.cpp).
#pragma once

#include <wheelchair_planner/config_space.h>

#include <vector>

namespace wheelchair_planner {

/// 8-connected Dijkstra distance [m] from every cell to the goal cell over the cells whose
/// obstacle distance is at least `axle_radius` (where the chair's axle may be); +infinity where
/// the goal cannot be reached. A lower bound of the path length.
std::vector<double> geodesicToGoal(const ConfigSpace& cs, double axle_radius, int gx, int gy);

}  // namespace wheelchair_planner
