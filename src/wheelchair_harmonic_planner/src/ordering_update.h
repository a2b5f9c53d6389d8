// Elimination order for a map whose free cells changed a little, derived from the previous map's
// order instead of a new AMD run (internal header of the direct solver, log_cholesky.h).
//
// Cells that stay free keep their relative order. Removing cells can only remove fill (the
// filled graph of an induced subgraph in the inherited order is a subgraph of the old one's).
// A new free cell is eliminated just before the earliest-eliminated of the old cells it touches
// (directly, or through other new cells: breadth-first, the farthest first), so its fill joins
// only cells near it (appended last instead, 282 new cells on maze1024 cost +11 % fill, not
// +0.3 %): the factor stays as local as AMD's, which the extended-exponent solves
// need (a geometric nested dissection, whose fill joins cells far apart along a maze's
// passages, gave L entries down to 1e-300 and below on maze2048, i.e. lost precision).
#pragma once

#include <wheelchair_harmonic_planner/harmonic_solver.h>

#include "large_blocks.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace wheelchair_harmonic_planner {

/// The unknown at each position of the derived order (CHOLMOD's Perm), or empty if `previous`
/// is for another grid size or more than `max_added` cells became free or more than
/// `max_removed` were blocked (then a new order is better). `free`: the new free-cell mask;
/// `cells`/`id`: the new unknowns' grid cells (row-major) and the unknown of each grid cell
/// (-1 if not free). Every free cell's four neighbours must lie in the grid.
LargeVector<int> deriveOrdering(const FactorOrdering& previous, const std::vector<uint8_t>& free,
                                const LargeVector<size_t>& cells, const LargeVector<int>& id,
                                long width, size_t max_added, size_t max_removed);

}  // namespace wheelchair_harmonic_planner
