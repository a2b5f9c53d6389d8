// Following the harmonic potential from the start to the goal (paper, Algorithm 2, last step).
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_harmonic_planner/harmonic_solver.h>

#include <string>
#include <vector>

namespace wheelchair_harmonic_planner {

using wheelchair_core::Pose2D;

struct DescentParams {
  double step_cells = 0.5;  ///< step length along the interpolated gradient [cells]
  int max_steps_per_cell = 8;
};

struct DescentResult {
  bool reached_goal = false;
  std::string failure_reason;
  std::vector<Pose2D> path;  ///< world frame; yaw filled by assignHeadings()
  int steps = 0;
  int fallback_steps = 0;  ///< steps where the interpolated gradient did not improve the cell
  double min_gradient = 0.0;
};

/// Descends phi (= ascends log u) from a world start point. Each step follows the gradient of
/// the bilinearly interpolated log u (sub-cell); it is accepted only if it stays in a free cell
/// whose log u is not lower; otherwise the step goes to the best four-neighbour (the discrete
/// maximum principle guarantees one is strictly higher), so the descent always ends at the goal.
DescentResult descend(const ConfigSpace& cspace, const HarmonicSolution& solution, double start_x,
                      double start_y, const DescentParams& params = DescentParams());

}  // namespace wheelchair_harmonic_planner
