// The OMPL planner plugin used directly (no ROS): its plans pass the same footprint gate, every
// OMPL algorithm finds a collision-free path through a maze, failures with reasons, its keys.
#include <wheelchair_description_testing/chair_file.h>
#include <wheelchair_ompl_planner/ompl_planner.h>
#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner_test/footprint_worlds.h>
#include <wheelchair_planner_test/maze.h>
#include <wheelchair_planner_test/planner_contract.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace wheelchair_ompl_planner;
using wheelchair_core::OccupancyMap;
using wheelchair_planner::bruteSweepClearance;
using wheelchair_planner::ConfigSpace;
using wheelchair_planner::ConfigSpaceParams;
using wheelchair_planner::lCorner;
using wheelchair_planner::makeMaze;
using wheelchair_planner::mazePassageCentre;

// First in this binary: OMPL's seed only takes effect before the process's first OMPL plan.
TEST(FootprintGate, GatesTheOmplPluginsPlansToo) {
  const OccupancyMap map = lCorner(1.2);
  const Pose2D start{1.5, 1.1, 0.0}, goal{5.9, 5.0, M_PI / 2};
  for (const bool repair : {false, true}) {
    OmplPlanner planner;
    PlannerSettings settings = wheelchair_planner::chairBoxSettings();
    settings.gate.repair = repair;
    OmplPlannerConfig config;
    config.algorithm = "RRTConnect";
    config.seed = 7;
    planner.configure(settings, config);
    planner.setMap(map);
    std::vector<Pose2D> plan;
    Certificate cert;
    const bool ok = planner.makePlan(start, goal, plan, cert);
    EXPECT_TRUE(cert.footprint_checked);
    if (!repair) {
      // OMPL's shortest path cuts the corner at the disc's 5 cm: the tail hits; refused.
      EXPECT_FALSE(ok);
      EXPECT_NE(cert.failure_reason.find("would"), std::string::npos) << cert.failure_reason;
      EXPECT_TRUE(plan.empty());
    } else {
      ASSERT_TRUE(ok) << cert.failure_reason;
      EXPECT_EQ(cert.path_stage, "footprint_search");
      EXPECT_GE(bruteSweepClearance(map, start, plan), 0.05 - 0.015);
    }
  }
}

TEST(OmplPlanner, EveryPlannerFindsACollisionFreePathThroughAMaze) {
  const auto maze = makeMaze(120, 16, 4, 3);
  ConfigSpaceParams cp;
  const ConfigSpace cs(maze, cp);
  double sx, sy, gx, gy;
  mazePassageCentre(0, 0, 16, 4, 0.05, sx, sy);
  mazePassageCentre(4, 4, 16, 4, 0.05, gx, gy);
  for (const std::string type : {"RRTConnect", "RRTstar", "PRMstar", "BITstar"}) {
    OmplPlanner planner;
    // The 0.8 m passages are too narrow for the chair's 1.1 m body to turn: this test is
    // about the sampling stage, with a body that fits in the C-space's disc.
    PlannerSettings settings;
    settings.footprint = {{0.2, 0.2}, {-0.2, 0.2}, {-0.2, -0.2}, {0.2, -0.2}};
    OmplPlannerConfig config;
    config.algorithm = type;
    config.time_limit = 1.0;
    config.simplify = true;
    planner.configure(settings, config);
    planner.setMap(maze);
    std::vector<Pose2D> plan;
    Certificate cert;
    ASSERT_TRUE(planner.makePlan({sx, sy, 0.0}, {gx, gy, 1.0}, plan, cert))
        << type << ": " << cert.failure_reason;
    EXPECT_TRUE(pathIsCollisionFree(cs, plan)) << type;
    EXPECT_NEAR(plan.back().x, gx, 1e-9);
    EXPECT_DOUBLE_EQ(plan.back().yaw, 1.0);
    // Sampling planners check motions at discrete steps: half a cell of tolerance.
    EXPECT_GE(cert.min_clearance, 0.05 - 0.025) << type;
  }
  OmplPlanner bad;
  OmplPlannerConfig dijkstra;
  dijkstra.algorithm = "Dijkstra";
  EXPECT_THROW(bad.configure(PlannerSettings(), dijkstra), wheelchair_core::ConfigError);
}

TEST(OmplPlanner, FailsClearlyForBadStartsAndGoals) {
  OmplPlanner planner;
  OmplPlannerConfig config;
  config.time_limit = 0.2;
  planner.configure(
      wheelchair_planner::plannerSettings(wheelchair_description::test::shippedChair()), config);
  wheelchair_planner::expectClearFailuresForBadStartsAndGoals(planner);
}

// Its keys, read as the host reads them; bad values are refused with what is wrong.
TEST(OmplPlanner, ReadsItsKeysAndRefusesBadValues) {
  const auto refusal = [](const std::string& yaml) {
    OmplPlanner planner;
    return wheelchair_planner::configureRefusal(planner, wheelchair_planner::chairBoxSettings(),
                                                yaml);
  };
  EXPECT_EQ(refusal("{algorithm: BITstar, time_limit: 0.5, simplify: false, seed: 3}"), "");
  EXPECT_NE(refusal("{algorithm: Dijkstra}").find("unknown algorithm 'Dijkstra'"),
            std::string::npos);
  EXPECT_NE(refusal("{time_limit: 0}").find("time_limit must be positive"), std::string::npos);
  EXPECT_NE(refusal("{solver: sor}").find("unknown parameter 'solver'"), std::string::npos)
      << "another plugin's key";
}
