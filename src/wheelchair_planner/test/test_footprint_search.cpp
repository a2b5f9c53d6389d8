// The footprint search leaving flat's side rooms (issue 24): a chair parked in the study or the
// bathroom facing into it (its rear to the 80 cm door onto the 1.2 m hallway) cannot turn there
// nor in the hallway; the search's forward and backward runs meet (backing out of the room and
// the way along the hallway), well inside the one budget, and the whole executed sweep keeps the
// minimum clearance by an independent brute-force check. A backward run's path is driven the
// other way round; with reverse off, backward runs do not bring reverse motion in.
#include <wheelchair_core/map_io.h>
#include <wheelchair_core/path_direction.h>
#include <wheelchair_planner/footprint_search.h>
#include <wheelchair_planner/planning_map.h>
#include <wheelchair_planner_test/footprint_worlds.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

using namespace wheelchair_planner;
using wheelchair_core::OccupancyMap;

namespace {

const Pose2D kLivingCentre{3.0, 2.2, 0.0};

/// The search as the footprint gate runs it (its clearances from the C-space), without a
/// time limit that the machine's load could reach: the budget that decides is the expansions.
FootprintSearchParams gateSearch(const PlannerSettings& settings) {
  FootprintSearchParams search = settings.gate.search;
  search.min_clearance = settings.cspace.min_clearance;
  search.soft_clearance = std::max(settings.cspace.clearance_band, settings.cspace.min_clearance);
  search.time_limit = 120.0;
  return search;
}

void expectLeavesForTheLivingRoom(const Pose2D& start, const std::string& room) {
  const OccupancyMap map = wheelchair_core::loadMap(std::string(WORLDS_DIR) + "/flat.yaml");
  const PlannerSettings settings = chairBoxSettings();
  const PlanningMap planning(map, settings);
  const FootprintSearchParams search = gateSearch(settings);
  const FootprintSearchResult r =
      footprintSearch(planning.checker(), start, kLivingCentre, search, settings.gate.sweep);
  ASSERT_TRUE(r.found) << room << ": " << r.reason;
  // Well inside the budget (200 000 expansions): before the runs met, 200 000 found nothing.
  EXPECT_LT(r.expansions, 60000u) << room;
  ASSERT_GE(r.path.size(), 3u);
  EXPECT_NEAR(r.path.front().x, start.x, 1e-9);
  EXPECT_NEAR(r.path.front().y, start.y, 1e-9);
  EXPECT_NEAR(r.path.back().x, kLivingCentre.x, 1e-9);
  EXPECT_NEAR(r.path.back().y, kLivingCentre.y, 1e-9);
  EXPECT_NEAR(r.path.back().yaw, kLivingCentre.yaw, 1e-9);
  // It backs out (the first piece is driven in reverse), within the limits.
  const auto pieces = wheelchair_core::splitAtCusps(r.path);
  ASSERT_FALSE(pieces.empty());
  EXPECT_EQ(pieces.front().direction, wheelchair_core::Direction::kReverse) << room;
  EXPECT_LE(wheelchair_core::cuspCount(r.path), static_cast<size_t>(search.max_cusps));
  EXPECT_GT(wheelchair_core::reversedLength(r.path), 0.5);
  EXPECT_LE(wheelchair_core::reversedLength(r.path), search.max_reverse_length + 0.05);
  EXPECT_TRUE(r.sweep.ok);
  EXPECT_GE(r.sweep.min_clearance, search.min_clearance);
  // Independent: brute-force clearance of the controller's execution of this plan.
  EXPECT_GE(bruteSweepClearance(map, start, r.path), search.min_clearance - 0.015) << room;
}

}  // namespace

TEST(FootprintSearch, BacksOutOfTheStudyFacingIntoItAndReachesTheLivingRoom) {
  expectLeavesForTheLivingRoom({7.0, 7.4, 0.0}, "study");
}

TEST(FootprintSearch, BacksOutOfTheBathroomFacingIntoItAndReachesTheLivingRoom) {
  expectLeavesForTheLivingRoom({3.3, 7.2, M_PI}, "bathroom");
}

// A 1.2 m dead end, the chair facing its end, the goal 3 m behind it: a backward run alone
// searches from the goal forwards into the dead end; the chair drives that path the other way
// round, straight back, every pose facing the dead end's end.
TEST(FootprintSearch, ABackwardRunsPathIsDrivenTheOtherWayRound) {
  const OccupancyMap map = carved(7.0, {{0.5, 6.5, 2.9, 4.1}});
  const PlannerSettings settings = chairBoxSettings();
  const PlanningMap planning(map, settings);
  FootprintSearchParams search = gateSearch(settings);
  search.attempts = {{2.0, 0.0, 0.15, true}};
  const Pose2D start{5.0, 3.5, 0.0}, goal{2.0, 3.5, 0.0};
  const FootprintSearchResult r =
      footprintSearch(planning.checker(), start, goal, search, settings.gate.sweep);
  ASSERT_TRUE(r.found) << r.reason;
  EXPECT_NEAR(r.path.front().x, start.x, 1e-9);
  EXPECT_NEAR(r.path.back().x, goal.x, 1e-9);
  EXPECT_EQ(wheelchair_core::cuspCount(r.path), 0u);
  EXPECT_NEAR(wheelchair_core::reversedLength(r.path), 3.0, 0.05);
  EXPECT_NEAR(r.reversed_length, 3.0, 0.05);
  for (const Pose2D& p : r.path) EXPECT_LT(std::abs(std::remainder(p.yaw, 2 * M_PI)), 0.1);
  EXPECT_GE(bruteSweepClearance(map, start, r.path), search.min_clearance - 0.015);
}

// Forwards only: the backward runs may only use what the chair drives forwards, so the dead end
// is refused (turning round needs a 1.72 m circle) and the reason says so.
TEST(FootprintSearch, WithReverseOffTheBackwardRunsBringNoReverseMotion) {
  const OccupancyMap map = carved(7.0, {{0.5, 6.5, 2.9, 4.1}});
  const PlannerSettings settings = chairBoxSettings();
  const PlanningMap planning(map, settings);
  FootprintSearchParams search = gateSearch(settings);
  search.reverse = false;
  search.max_expansions = 30000;
  search.attempts = {{2.0, 0.0, 0.15, false}, {2.0, 0.0, 0.15, true}};
  const FootprintSearchResult r = footprintSearch(planning.checker(), {5.0, 3.5, 0.0},
                                                  {2.0, 3.5, 0.0}, search, settings.gate.sweep);
  EXPECT_FALSE(r.found) << "reversed " << wheelchair_core::reversedLength(r.path);
  EXPECT_NE(r.reason.find("forwards only"), std::string::npos) << r.reason;
}

// The way round of navigation_around (issue 22): flat with a 0.4 m disc the map does not have in
// the 1.15 m gap east of the dining table, the chair stopped south of the table facing the gap
// (as the navigator stopped it, 2026-12-02), the goal kitchen_door (facing back into the living
// room, where the body cannot turn: only a way in backwards fits). The search finds the way
// round the table's north side, never through the gap, whose executed sweep keeps the minimum
// clearance by the brute-force check. Its wall time is printed (the issue asks <= 20 ms for a
// replan on flat; asserted is the work, not the time: the machine is shared).
TEST(FootprintSearch, TheWayRoundTheDiningTableWithTheGapBlockedIsFoundQuickly) {
  OccupancyMap map = wheelchair_core::loadMap(std::string(WORLDS_DIR) + "/flat.yaml");
  const double bx = 5.425, by = 3.30, br = 0.20;  // the disc in the gap
  for (int iy = 0; iy < map.height; ++iy) {
    for (int ix = 0; ix < map.width; ++ix) {
      double x, y;
      map.cellToWorld(ix, iy, x, y);
      if (std::hypot(x - bx, y - by) <= br) map.at(ix, iy) = wheelchair_core::kOccupied;
    }
  }
  const PlannerSettings settings = chairBoxSettings();
  const PlanningMap planning(map, settings);
  const FootprintSearchParams search = gateSearch(settings);
  const Pose2D start{4.0, 2.15, 0.0}, goal{6.90, 4.85, M_PI};
  FootprintSearchResult r;
  std::vector<double> times, cpu;  // wall (the search's own) and CPU time [s]
  for (int run = 0; run < 5; ++run) {
    const std::clock_t c0 = std::clock();
    r = footprintSearch(planning.checker(), start, goal, search, settings.gate.sweep);
    cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    ASSERT_TRUE(r.found) << r.reason;
    times.push_back(r.time);
  }
  std::sort(times.begin(), times.end());
  std::sort(cpu.begin(), cpu.end());
  std::printf(
      "way round the dining table: %zu expansions, wall %.1f ms (min of 5), %.1f ms (median), "
      "CPU %.1f ms (min of 5)\n",
      r.expansions, 1e3 * times.front(), 1e3 * times[2], 1e3 * cpu.front());
  EXPECT_LT(r.expansions, 3000u);
  EXPECT_NEAR(r.path.back().x, goal.x, 1e-9);
  EXPECT_NEAR(r.path.back().y, goal.y, 1e-9);
  bool north = false;
  for (const Pose2D& p : r.path) {
    EXPECT_FALSE(p.x > 4.85 && p.x < 6.0 && p.y > 2.8 && p.y < 3.8)
        << "through the blocked gap at (" << p.x << ", " << p.y << ")";
    north = north || (p.x > 3.6 && p.x < 4.85 && p.y > 3.8);
  }
  EXPECT_TRUE(north) << "not round the table's north side";
  EXPECT_GE(bruteSweepClearance(map, start, r.path), search.min_clearance - 0.015);
}
