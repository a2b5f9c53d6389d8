// Descent on the harmonic potential: no local minima (the goal is reached from every free cell
// of random mazes and of the test worlds), and the 200 m corridor where the paper's linear
// formulation stalls.
#include <wheelchair_core/map_io.h>
#include <wheelchair_harmonic_planner/gradient_descent.h>
#include <wheelchair_harmonic_planner/harmonic_solver.h>
#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner_test/maze.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace wheelchair_harmonic_planner;
using namespace wheelchair_planner;
using wheelchair_core::OccupancyMap;

namespace {

/// Descends from every `stride`-th reachable cell and checks each path ends at the goal cell
/// inside free C-space.
void expectDescentFromEveryCell(const ConfigSpace& cs, const HarmonicSolution& s, int stride,
                                const std::string& what) {
  int tried = 0;
  for (int iy = 0; iy < cs.height(); iy += stride) {
    for (int ix = 0; ix < cs.width(); ix += stride) {
      if (!s.reachable(ix, iy)) continue;
      double x, y;
      cs.gridToWorld(ix, iy, x, y);
      const DescentResult d = descend(cs, s, x, y);
      ++tried;
      ASSERT_TRUE(d.reached_goal) << what << " from cell " << ix << "," << iy << ": "
                                  << d.failure_reason;
      ASSERT_TRUE(pathIsCollisionFree(cs, d.path)) << what << " from " << ix << "," << iy;
      int gx, gy;
      ASSERT_TRUE(cs.worldToCell(d.path.back().x, d.path.back().y, gx, gy));
      ASSERT_EQ(gx, s.goal_ix);
      ASSERT_EQ(gy, s.goal_iy);
    }
  }
  EXPECT_GT(tried, 50) << what;
}

}  // namespace

TEST(Descent, ReachesTheGoalFromEveryFreeCellOfRandomMazes) {
  ConfigSpaceParams p;
  p.inscribed_radius = 0.05;
  p.min_clearance = 0.0;
  p.clearance_band = 0.1;  // the band's conductance is active in these corridors
  for (uint32_t seed = 1; seed <= 3; ++seed) {
    const ConfigSpace cs(makeMaze(97, 7, 2, seed), p);
    const HarmonicSolution s = solveHarmonic(cs, 48, 48, HarmonicSolverParams());
    ASSERT_TRUE(s.converged);
    expectDescentFromEveryCell(cs, s, 1, "maze seed " + std::to_string(seed));
  }
}

TEST(Descent, ReachesTheGoalFromFreeCellsOfTheTestWorlds) {
  const std::string dir = WORLDS_DIR;
  // office and hall (1200 x 480 and 1000 x 1000 cells) take minutes to solve: bench/planners.
  for (const std::string world : {"flat", "symmetric"}) {
    const std::string path = dir + "/" + world + ".yaml";
    if (!std::ifstream(path).good()) GTEST_SKIP() << "test worlds not found at " << dir;
    const ConfigSpace cs(wheelchair_core::loadMap(path), ConfigSpaceParams());
    // Goal: the free cell of largest clearance.
    int gx = 0, gy = 0;
    for (int iy = 0; iy < cs.height(); ++iy)
      for (int ix = 0; ix < cs.width(); ++ix)
        if (cs.isFree(ix, iy) && cs.obstacleDistance(ix, iy) > cs.obstacleDistance(gx, gy)) {
          gx = ix;
          gy = iy;
        }
    const HarmonicSolution s = solveHarmonic(cs, gx, gy, HarmonicSolverParams());
    ASSERT_TRUE(s.converged) << world;
    expectDescentFromEveryCell(cs, s, 3, world);
  }
}

// 200 m of a 1 m corridor (the chair's C-space leaves 0.28 m): u falls to about e^-2200 at the
// far end. The paper's phi = 1 - u is exactly 1.0 in double beyond a few metres, so its
// gradient is zero there; our log-space solution descends all the way.
TEST(Descent, TwoHundredMetreCorridorPaperFormulationStallsOursReachesTheGoal) {
  const ConfigSpace cs(makeCorridor(200.0, 1.0, 0.05), ConfigSpaceParams());
  const int mid = cs.height() / 2;
  const int goal_x = 12;  // 2 wall cells + 0.36 m of C-space dilation
  ASSERT_TRUE(cs.isFree(goal_x, mid)) << "corridor C-space closed";
  const HarmonicSolution s = solveHarmonic(cs, goal_x, mid, HarmonicSolverParams());
  ASSERT_TRUE(s.converged) << s.residual;
  double sx, sy;
  cs.gridToWorld(cs.width() - 13, mid, sx, sy);
  const DescentResult ours = descend(cs, s, sx, sy);
  ASSERT_TRUE(ours.reached_goal) << ours.failure_reason;
  EXPECT_NEAR(pathLength(ours.path), (cs.width() - 13 - goal_x) * 0.05, 0.5);
  EXPECT_GT(ours.min_gradient, 0.0);

  // The paper's phi, even taken from the exact solution, is 1.0 (flat) at the start.
  int flat_cells = 0, free_cells = 0;
  for (int ix = 0; ix < cs.width(); ++ix) {
    if (!s.reachable(ix, mid)) continue;
    ++free_cells;
    if (1.0 - std::exp(s.at(ix, mid)) == 1.0) ++flat_cells;
  }
  EXPECT_GT(flat_cells, 0.95 * free_cells);
  // And the paper's Jacobi iteration stops (max |delta phi| < 1e-12, its own criterion) with the
  // start still at phi = 1: descent on it stalls.
  const JacobiResult jacobi = solvePaperJacobi(cs, goal_x, mid, 1e-12, 3000);
  EXPECT_EQ(jacobi.phi[cs.index(cs.width() - 13, mid)], 1.0);
  HarmonicSolution paper = s;
  for (size_t k = 0; k < paper.log_u.size(); ++k)
    paper.log_u[k] =
        cs.freeMask()[k] && jacobi.phi[k] < 1.0 ? std::log(1.0 - jacobi.phi[k]) : -INFINITY;
  const DescentResult stalled = descend(cs, paper, sx, sy);
  EXPECT_FALSE(stalled.reached_goal);
  EXPECT_FALSE(stalled.failure_reason.empty());
}

TEST(Descent, StartInObstacleOrDisconnectedFailsWithAReason) {
  OccupancyMap m = makeCorridor(4.0, 1.2, 0.05);
  for (int iy = 0; iy < m.height; ++iy) m.at(40, iy) = wheelchair_core::kOccupied;  // a wall
  const ConfigSpace cs(m, ConfigSpaceParams());
  const HarmonicSolution s = solveHarmonic(cs, 15, 14, HarmonicSolverParams());
  const DescentResult wall = descend(cs, s, 40 * 0.05 + 0.02, 0.7);
  EXPECT_FALSE(wall.reached_goal);
  EXPECT_NE(wall.failure_reason.find("not in free C-space"), std::string::npos)
      << wall.failure_reason;
  const DescentResult other_side = descend(cs, s, 3.0, 0.7);
  EXPECT_FALSE(other_side.reached_goal);
  EXPECT_NE(other_side.failure_reason.find("not connected"), std::string::npos)
      << other_side.failure_reason;
}
