// The two planner plugins used directly (no ROS): the flat's 80 cm doorways, clearance where
// space allows, failures with reasons, every OMPL planner on a maze.
#include <wheelchair_core/map_io.h>
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_harmonic_planner/maze.h>
#include <wheelchair_harmonic_planner/ompl_planner.h>
#include <wheelchair_harmonic_planner/path_metrics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

using namespace wheelchair_harmonic_planner;

namespace {

double distanceTo(const Pose2D& p, double x, double y) { return std::hypot(p.x - x, p.y - y); }

}  // namespace

// Toilet (bathroom) to desk (study): through two 80 cm doors (flat.doors.yaml: hallway_bathroom
// at (4.45, 7.2), hallway_study at (5.75, 7.4)) and the 1.2 m hallway between them.
TEST(HarmonicPlanner, PassesThe80cmDoorsOfFlatAndKeeps20cmInOpenSpace) {
  const std::string path = std::string(WORLDS_DIR) + "/flat.yaml";
  if (!std::ifstream(path).good()) GTEST_SKIP() << "test world not found: " << path;
  HarmonicPlanner planner;
  planner.initialize("harmonic", wheelchair_core::loadMap(path), {{"inscribed_radius", "0.31"}});
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
  const ParameterMap lazy{{"inscribed_radius", "0.31"}, {"prepare_on_map", "false"}};
  const ParameterMap eager{{"inscribed_radius", "0.31"}};
  HarmonicPlanner late, early;
  late.initialize("late", maze, lazy);
  early.initialize("early", maze, eager);
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
  early.initialize("early", changed, eager);
  EXPECT_EQ(early.factorCache().factorizations, 1);
  EXPECT_TRUE(early.makePlan(start, goal, early_plan, early_cert)) << early_cert.failure_reason;
  EXPECT_TRUE(early_cert.warm_started);
  HarmonicPlanner bad;
  EXPECT_THROW(bad.initialize("bad", maze, {{"prepare_on_map", "often"}}), std::invalid_argument);
}

TEST(HarmonicPlanner, FailsClearlyForBadStartsAndGoals) {
  auto map = makeCorridor(6.0, 1.2, 0.05);
  for (int iy = 0; iy < map.height; ++iy) map.at(60, iy) = wheelchair_core::kOccupied;
  for (GlobalPlanner* planner :
       std::initializer_list<GlobalPlanner*>{new HarmonicPlanner, new OmplPlanner}) {
    std::unique_ptr<GlobalPlanner> owner(planner);
    planner->initialize("p", map, {{"time_limit", "0.2"}});
    std::vector<Pose2D> plan;
    Certificate cert;
    const Pose2D ok{1.0, 0.7, 0.0};
    EXPECT_FALSE(planner->makePlan(ok, {3.02, 0.7, 0.0}, plan, cert));
    EXPECT_NE(cert.failure_reason.find("goal"), std::string::npos) << cert.failure_reason;
    EXPECT_NE(cert.failure_reason.find("obstacle"), std::string::npos) << cert.failure_reason;
    EXPECT_TRUE(plan.empty());
    EXPECT_FALSE(planner->makePlan({-1.0, 0.7, 0.0}, ok, plan, cert));
    EXPECT_NE(cert.failure_reason.find("outside the map"), std::string::npos);
    EXPECT_FALSE(planner->makePlan(ok, {5.0, 0.7, 0.0}, plan, cert));  // beyond the wall
    EXPECT_FALSE(cert.failure_reason.empty());
    EXPECT_TRUE(plan.empty());
    EXPECT_FALSE(planner->makePlan(ok, {NAN, 0.7, 0.0}, plan, cert));
    EXPECT_NE(cert.failure_reason.find("not finite"), std::string::npos);
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
    planner.initialize("ompl", maze,
                       {{"algorithm", type},
                        {"time_limit", "1.0"},
                        {"simplify", "true"},
                        {"footprint", "0.2,0.2;-0.2,0.2;-0.2,-0.2;0.2,-0.2"}});
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
  EXPECT_THROW(bad.initialize("ompl", maze, {{"algorithm", "Dijkstra"}}), std::invalid_argument);
}
