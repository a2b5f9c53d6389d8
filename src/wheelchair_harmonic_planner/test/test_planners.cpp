// The harmonic planner plugin used directly (no ROS): the flat's 80 cm doorways, clearance where
// space allows, the map prepared on arrival, failures with reasons, its own keys.
#include <wheelchair_core/map_io.h>
#include <wheelchair_description_testing/chair_file.h>
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner_test/maze.h>
#include <wheelchair_planner_test/planner_contract.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

using namespace wheelchair_harmonic_planner;
using wheelchair_planner::makeCorridor;
using wheelchair_planner::makeMaze;
using wheelchair_planner::mazePassageCentre;

namespace {

double distanceTo(const Pose2D& p, double x, double y) { return std::hypot(p.x - x, p.y - y); }

/// The settings the host gives for the chair of wheelchair_description's chair.yaml.
PlannerSettings chairSettings() {
  return wheelchair_planner::plannerSettings(wheelchair_description::test::shippedChair());
}

HarmonicPlannerConfig lazy() {
  HarmonicPlannerConfig config;
  config.prepare_on_map = false;
  return config;
}

}  // namespace

// Toilet (bathroom) to desk (study): through two 80 cm doors (flat.doors.yaml: hallway_bathroom
// at (4.45, 7.2), hallway_study at (5.75, 7.4)) and the 1.2 m hallway between them.
TEST(HarmonicPlanner, PassesThe80cmDoorsOfFlatAndKeeps20cmInOpenSpace) {
  const std::string path = std::string(WORLDS_DIR) + "/flat.yaml";
  if (!std::ifstream(path).good()) GTEST_SKIP() << "test world not found: " << path;
  HarmonicPlanner planner;
  planner.configure(chairSettings(), HarmonicPlannerConfig());
  planner.setMap(wheelchair_core::loadMap(path));
  std::vector<Pose2D> plan;
  Certificate cert;
  ASSERT_TRUE(planner.makePlan({2.90, 7.25, 0.0}, {8.80, 7.50, 0.0}, plan, cert))
      << cert.failure_reason;
  EXPECT_TRUE(cert.solver_converged);
  EXPECT_TRUE(cert.descent_reached_goal);
  EXPECT_GE(cert.min_clearance, 0.05 - 1e-6);
  ASSERT_EQ(cert.clearance.size(), plan.size());
  const double doors[2][2] = {{4.45, 7.2}, {5.75, 7.4}};
  for (const auto& d : doors) {
    double nearest = 1e9;
    for (const Pose2D& p : plan) nearest = std::min(nearest, distanceTo(p, d[0], d[1]));
    EXPECT_LT(nearest, 0.1) << "the path misses the door at " << d[0] << ", " << d[1];
  }
  // Away from the doorways (0.6 m) the free space allows 20 cm, and the path keeps it.
  int open_points = 0;
  for (size_t i = 0; i < plan.size(); ++i) {
    if (distanceTo(plan[i], doors[0][0], doors[0][1]) < 0.6 ||
        distanceTo(plan[i], doors[1][0], doors[1][1]) < 0.6)
      continue;
    ++open_points;
    EXPECT_GE(cert.clearance[i], 0.20 - 0.01) << "at " << plan[i].x << ", " << plan[i].y;
  }
  EXPECT_GT(open_points, 20);
}

// The map's factorization happens when the map arrives, so that the rider's first goal costs
// only the solves; the plan is the same as with the factorization in makePlan. During a drive (a
// goal tracked) a new map is not factored up front: the replan checks the earlier field first.
TEST(HarmonicPlanner, FactorsANewMapOnArrivalAndTheFirstGoalOnlySolves) {
  const auto maze = makeMaze(200, 36, 4, 2);
  double sx, sy, gx, gy;
  mazePassageCentre(0, 0, 36, 4, 0.05, sx, sy);
  mazePassageCentre(3, 3, 36, 4, 0.05, gx, gy);
  const Pose2D start{sx, sy, 0.0}, goal{gx, gy, 0.0};
  HarmonicPlanner late, early;
  late.configure(chairSettings(), lazy());
  early.configure(chairSettings(), HarmonicPlannerConfig());
  late.setMap(maze);
  early.setMap(maze);
  EXPECT_EQ(late.factorCache().factorizations, 0);
  EXPECT_EQ(early.factorCache().factorizations, 1);
  std::vector<Pose2D> late_plan, early_plan;
  Certificate late_cert, early_cert;
  ASSERT_TRUE(late.makePlan(start, goal, late_plan, late_cert)) << late_cert.failure_reason;
  ASSERT_TRUE(early.makePlan(start, goal, early_plan, early_cert)) << early_cert.failure_reason;
  EXPECT_EQ(late.factorCache().factorizations, 1);
  EXPECT_EQ(early.factorCache().factorizations, 1) << "the first goal factored the map again";
  ASSERT_EQ(late_plan.size(), early_plan.size());
  for (size_t i = 0; i < late_plan.size(); ++i) {
    EXPECT_EQ(late_plan[i].x, early_plan[i].x);
    EXPECT_EQ(late_plan[i].y, early_plan[i].y);
  }
  // A small change far from the route while the goal is tracked: no factorization on arrival,
  // the replan keeps (warm start) or recomputes the field, and still reaches the goal.
  auto changed = maze;
  for (int iy = 150; iy < 154; ++iy)
    for (int ix = 20; ix < 24; ++ix) changed.at(ix, iy) = wheelchair_core::kOccupied;
  early.setMap(changed);
  EXPECT_EQ(early.factorCache().factorizations, 1);
  EXPECT_TRUE(early.makePlan(start, goal, early_plan, early_cert)) << early_cert.failure_reason;
  EXPECT_TRUE(early_cert.warm_started);
}

TEST(HarmonicPlanner, FailsClearlyForBadStartsAndGoals) {
  HarmonicPlanner planner;
  planner.configure(chairSettings(), HarmonicPlannerConfig());
  wheelchair_planner::expectClearFailuresForBadStartsAndGoals(planner);
}

// Its keys, read as the host reads them; a value that is not a boolean, an unknown solver and the
// removed multigrid solver are refused with what is wrong.
TEST(HarmonicPlanner, ReadsItsKeysAndRefusesBadValuesAndTheRemovedMultigridSolver) {
  const auto refusal = [](const std::string& yaml) {
    HarmonicPlanner planner;
    return wheelchair_planner::configureRefusal(planner, chairSettings(), yaml);
  };
  EXPECT_EQ(refusal("{solver: sor, tolerance: 1e-6, max_iterations: 500, omega: 1.5,"
                    " sweeps_per_rescale: 4, prepare_on_map: false}"),
            "");
  EXPECT_NE(refusal("{prepare_on_map: often}").find("prepare_on_map"), std::string::npos);
  EXPECT_NE(refusal("{solver: multigrid}").find("'multigrid' was removed"), std::string::npos);
  EXPECT_NE(refusal("{solver: jacobi}").find("'direct' or 'sor'"), std::string::npos);
  EXPECT_NE(refusal("{omega: 2.0}").find("omega"), std::string::npos);
  EXPECT_NE(refusal("{algorithm: RRTstar}").find("unknown parameter 'algorithm'"),
            std::string::npos)
      << "another plugin's key";
}
