// The discrete operator shared by the harmonic solvers (direct and SOR): internal header.
#pragma once

#include <wheelchair_harmonic_planner/harmonic_solver.h>

#include <cstdint>
#include <vector>

namespace wheelchair_harmonic_planner {

/// Free cells connected to the goal (4-neighbourhood) with their breadth-first distance; -1 for
/// every other cell.
std::vector<int> reachableDistances(const ConfigSpace& cs, size_t goal);

/// For free cell k, u_k = sum_j w_kj u_j / sum_j w_kj over its four neighbours; edge conductance
/// w_kj = (sigma_k + sigma_j) / 2 (sigma_j := sigma_k for obstacles, whose u is 0). With
/// sigma = 1 this is the paper's four-neighbour average (Algorithm 2).
struct Stencil {
  std::vector<size_t> cells;    ///< free cells connected to the goal, goal excluded
  std::vector<double> weight;   ///< 4 normalized weights per listed cell (E, W, N, S)
  std::vector<double> total;    ///< sum of the cell's 4 edge conductances (incl. to obstacles)
  std::vector<uint8_t> active;  ///< 1 for cells whose log u is finite (incl. goal)
};

Stencil buildStencil(const ConfigSpace& cs, const std::vector<int>& dist, size_t goal,
                     bool use_conductance);

/// Convergence criterion of an earlier solution (e.g. for the same goal before the map changed)
/// on `cs`, without building a stencil: max over the free cells with finite log u but the goal
/// of the relative residual; +infinity if the connectivity changed (a free cell with -inf next
/// to a free cell with finite log u, or the goal not free). Stops once above `give_up_above`.
double earlierSolutionResidual(const ConfigSpace& cs, const std::vector<double>& log_u, size_t goal,
                               bool use_conductance, double give_up_above);

/// Max over the stencil's cells of the relative residual |sum_j w_kj u_j / u_k - 1| of the log
/// field l (the convergence criterion); also returns the scaled coefficients
/// a_kj = w_kj exp(l_j - l_k) in `a` (4 per listed cell) if `a` is not null.
double relativeResidual(const Stencil& s, const std::vector<double>& l, long width,
                        std::vector<double>* a);

}  // namespace wheelchair_harmonic_planner
