// The harmonic planner plugin used directly (no ROS): the flat's 80 cm doorways, clearance where
// space allows, the map prepared on arrival, failures with reasons, its own keys.
#include <wheelchair_core/map_io.h>
#include <wheelchair_description_testing/chair_file.h>
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner/planning_map.h>
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

// ---- Map changes: the live obstacle layer over the static map (updateMap) -----------------

namespace {

/// 9 m x 5 m, two rooms split by a wall at x = 4.4-4.6 m with a 1 m door near the bottom
/// (y 0.8-1.8) and one near the top (y 3.2-4.2).
wheelchair_core::OccupancyMap twoDoorRooms() {
  wheelchair_core::OccupancyMap m;
  m.resolution = 0.05;
  m.width = 180;
  m.height = 100;
  m.data.assign(static_cast<size_t>(m.width) * m.height, wheelchair_core::kFree);
  for (int iy = 0; iy < m.height; ++iy) {
    for (int ix = 0; ix < m.width; ++ix) {
      double x, y;
      m.cellToWorld(ix, iy, x, y);
      const bool border = x < 0.1 || y < 0.1 || x > 8.9 || y > 4.9;
      const bool wall = x > 4.4 && x < 4.6 && !(y > 0.8 && y < 1.8) && !(y > 3.2 && y < 4.2);
      if (border || wall) m.at(ix, iy) = wheelchair_core::kOccupied;
    }
  }
  return m;
}

/// An obstacle layer on `m`'s grid with the box [x0, x1] x [y0, y1] occupied.
wheelchair_core::OccupancyMap layerWithBox(const wheelchair_core::OccupancyMap& m, double x0,
                                           double y0, double x1, double y1,
                                           wheelchair_core::OccupancyMap layer = {}) {
  if (layer.data.empty()) {
    layer = m;
    layer.data.assign(m.data.size(), wheelchair_core::kUnknown);
  }
  for (int iy = 0; iy < m.height; ++iy) {
    for (int ix = 0; ix < m.width; ++ix) {
      double x, y;
      m.cellToWorld(ix, iy, x, y);
      if (x >= x0 && x <= x1 && y >= y0 && y <= y1) layer.at(ix, iy) = wheelchair_core::kOccupied;
    }
  }
  return layer;
}

/// Heights at which the plan crosses the dividing wall (x 4.4-4.6).
std::vector<double> wallCrossings(const std::vector<Pose2D>& plan) {
  std::vector<double> ys;
  for (const Pose2D& p : plan)
    if (p.x > 4.4 && p.x < 4.6) ys.push_back(p.y);
  return ys;
}

double pathLength(const std::vector<Pose2D>& plan) {
  double length = 0.0;
  for (size_t i = 1; i < plan.size(); ++i)
    length += std::hypot(plan[i].x - plan[i - 1].x, plan[i].y - plan[i - 1].y);
  return length;
}

}  // namespace

// The bottom door blocked by something the map does not have (a 0.6 m x 0.6 m box in the
// doorway, as the obstacle layer reports it), the top door free: the plan goes through the top
// door, found on the adapted factorization (no new one); the box gone, the plan goes through the
// bottom door again, as long as before; both doors blocked: no plan, with a reason.
TEST(HarmonicPlanner, ReplansThroughTheFreeDoorWhenTheObstacleLayerBlocksTheOther) {
  const wheelchair_core::OccupancyMap map = twoDoorRooms();
  HarmonicPlanner planner;
  planner.configure(chairSettings(), HarmonicPlannerConfig());
  planner.setMap(map);
  const Pose2D start{2.0, 1.3, 0.0}, goal{7.0, 1.3, 0.0};
  std::vector<Pose2D> plan;
  Certificate cert;
  ASSERT_TRUE(planner.makePlan(start, goal, plan, cert)) << cert.failure_reason;
  for (const double y : wallCrossings(plan)) EXPECT_TRUE(y > 0.8 && y < 1.8) << y;
  ASSERT_FALSE(wallCrossings(plan).empty());
  const double direct = pathLength(plan);
  EXPECT_EQ(planner.factorCache().factorizations, 1);

  const auto bottom_blocked = layerWithBox(map, 4.2, 1.0, 4.8, 1.6);
  planner.updateMap(wheelchair_planner::withObstacles(map, bottom_blocked));
  ASSERT_TRUE(planner.makePlan(start, goal, plan, cert)) << cert.failure_reason;
  ASSERT_FALSE(wallCrossings(plan).empty());
  for (const double y : wallCrossings(plan)) EXPECT_TRUE(y > 3.2 && y < 4.2) << y;
  EXPECT_GT(pathLength(plan), direct + 3.0);  // up to the top door and back down: ~2 x 2.4 m
  EXPECT_EQ(planner.factorCache().factorizations, 1) << "the map change needed a factorization";
  EXPECT_EQ(planner.factorCache().factor_updates, 1);

  planner.updateMap(map);  // the box was taken away
  ASSERT_TRUE(planner.makePlan(start, goal, plan, cert)) << cert.failure_reason;
  for (const double y : wallCrossings(plan)) EXPECT_TRUE(y > 0.8 && y < 1.8) << y;
  EXPECT_NEAR(pathLength(plan), direct, 0.01);
  EXPECT_EQ(planner.factorCache().factorizations, 1);
  EXPECT_EQ(planner.factorCache().factor_updates, 2);

  planner.updateMap(wheelchair_planner::withObstacles(
      map, layerWithBox(map, 4.2, 3.4, 4.8, 4.0, bottom_blocked)));
  EXPECT_FALSE(planner.makePlan(start, goal, plan, cert));
  EXPECT_FALSE(cert.failure_reason.empty());
  EXPECT_TRUE(plan.empty());
}

// The layer adds obstacles and never frees a map cell; another grid is refused.
TEST(HarmonicPlanner, TheObstacleLayerOnlyAddsObstaclesOnTheMapsOwnGrid) {
  const wheelchair_core::OccupancyMap map = twoDoorRooms();
  wheelchair_core::OccupancyMap layer = layerWithBox(map, 1.0, 1.0, 1.2, 1.2);
  layer.at(0, 0) = wheelchair_core::kFree;  // a map wall the layer saw free
  const auto merged = wheelchair_planner::withObstacles(map, layer);
  for (size_t k = 0; k < map.data.size(); ++k) {
    const int8_t expected =
        layer.data[k] == wheelchair_core::kOccupied ? wheelchair_core::kOccupied : map.data[k];
    ASSERT_EQ(merged.data[k], expected) << k;
  }
  layer.origin_x += 0.05;
  EXPECT_THROW(wheelchair_planner::withObstacles(map, layer), std::invalid_argument);
}
