// Multigrid for the log-space harmonic function (see README, "Solver"). With the current log
// field l, u = exp(l) v turns the discrete Laplace equation into a linear system for v whose
// coefficients a_kj = w_kj exp(l_j - l_k) are O(1) and whose solution is v = 1 once l is exact.
// That system is solved by V- or W-cycles: red-black Gauss-Seidel smoothing on the cell grid;
// coarse grids by 2x2 aggregation (a coarse cell holds the largest set of its four children
// connected inside the block, so it never joins two sides of a wall; obstacles and the goal
// are never unknowns, so they stay Dirichlet on every grid); Galerkin coarse operators of the
// unscaled equation (computed once per map and goal: M-matrices, so Gauss-Seidel converges on
// every level), rescaled per level by the log-mean-exp of the children's l. Then l += log v.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace wheelchair_harmonic_planner {

struct MultigridParams {
  int pre_smooth = 2;             ///< red-black Gauss-Seidel sweeps before the coarse correction
  int post_smooth = 2;            ///< ... and after it
  double correction_scale = 1.0;  ///< over-correction of the piecewise-constant prolongation
  int coarsest_unknowns = 300;    ///< stop coarsening at this many unknowns
  int coarsest_sweeps = 200;      ///< Gauss-Seidel sweeps on the coarsest grid
  double max_log_step = 3.0;      ///< bound on |log v| applied per rescaling
  int cycle_index = 1;            ///< coarse-grid visits per level: 1 = V-cycle, 2 = W-cycle
};

class ScaledMultigrid {
 public:
  /// `unknown`: cells whose log u is solved for (free, connected to the goal, not the goal);
  /// `weight`: 4 normalized stencil weights per grid cell (E, W, N, S), 0 toward cells whose
  /// u is 0 (obstacles); the goal cell (u = 1) is `goal`. The grid's outer ring must not
  /// contain unknowns.
  ScaledMultigrid(int width, int height, std::vector<uint8_t> unknown, std::vector<double> weight,
                  size_t goal, const MultigridParams& params);

  /// Scales the system by exp(l) (l = log u per cell, 0 at the goal) and resets v = 1. Returns
  /// the convergence criterion of l: max over unknowns of |sum_j w_kj u_j / u_k - 1|.
  double rescale(const std::vector<double>& log_u);
  /// One cycle on v.
  void vcycle();
  /// l += log v on the unknowns (bounded by max_log_step); returns max |log v|.
  double correct(std::vector<double>& log_u) const;

  int levels() const { return static_cast<int>(levels_.size()); }

 private:
  struct Level {
    int w = 0, h = 0;
    std::vector<uint8_t> unknown;
    std::vector<uint8_t> agg;                  ///< part of its coarse cell (prolongation row != 0)
    std::vector<double> sE, sW, sN, sS, diag;  ///< unscaled: diag u_k - sum s u_nbr = rhs
    std::vector<double> cE, cW, cN, cS;        ///< scaled couplings s exp(l_nbr - l_k)
    std::vector<double> l;                     ///< scaling log field of this level
    std::vector<double> t;                     ///< exp(l_k - l_coarse) for aggregated cells
    std::vector<double> v, f, r;
  };
  static Level aggregate(Level& fine);
  void scaleLevel(Level& lv) const;
  void smooth(Level& lv, int sweeps) const;
  void residual(Level& lv) const;
  void cycle(size_t l);

  MultigridParams params_;
  size_t goal_;
  std::vector<std::pair<size_t, double>> to_goal_;  ///< (cell, weight) of the goal's neighbours
  std::vector<Level> levels_;
};

}  // namespace wheelchair_harmonic_planner
