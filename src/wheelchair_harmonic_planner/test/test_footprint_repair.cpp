// The footprint gate with the harmonic plugin: the footprint search repairs the harmonic path in
// an L-corner (its sweep verified independently by a brute-force box-vs-cell test with the
// controller's own smoothing), backs out of a dead end the body cannot turn in (issue 24: a
// forward-only search refuses it), refuses a turn the body cannot make even backing and filling,
// saying what was tried and where, and spends its one budget to the end.
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_planner_test/footprint_worlds.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace wheelchair_harmonic_planner;
using wheelchair_core::OccupancyMap;
using wheelchair_planner::bruteSweepClearance;
using wheelchair_planner::carved;
using wheelchair_planner::lCorner;

#ifndef LCORNER_W
#define LCORNER_W 1.2
#endif

TEST(FootprintSearch, RepairsTheHarmonicPathInAnLCornerAndItsSweepHoldsIndependently) {
  const OccupancyMap map = lCorner(LCORNER_W);
  HarmonicPlanner planner;
  planner.configure(wheelchair_planner::chairBoxSettings(), HarmonicPlannerConfig());
  planner.setMap(map);
  std::vector<Pose2D> plan;
  Certificate cert;
  const Pose2D start{1.5, 0.5 + LCORNER_W / 2, 0.0}, goal{6.5 - LCORNER_W / 2, 5.0, M_PI / 2};
  ASSERT_TRUE(planner.makePlan(start, goal, plan, cert)) << cert.failure_reason;
  EXPECT_EQ(cert.path_stage, "footprint_search") << "the harmonic path's sweep should fail here";
  EXPECT_FALSE(cert.first_stage_sweep.empty());
  EXPECT_TRUE(cert.footprint_checked);
  EXPECT_GE(cert.footprint_clearance, 0.05);
  EXPECT_LT(cert.search_time, 5.0);
  EXPECT_NEAR(plan.back().x, goal.x, 1e-9);
  EXPECT_NEAR(plan.back().y, goal.y, 1e-9);
  // The piece that joins the goal continues the path: no sideways hop just before the goal.
  ASSERT_GE(plan.size(), 3u);
  const Pose2D& a = plan[plan.size() - 2];
  const Pose2D& b = plan[plan.size() - 3];
  const double join = std::atan2(plan.back().y - a.y, plan.back().x - a.x);
  const double arrive = std::atan2(a.y - b.y, a.x - b.x);
  if (std::hypot(plan.back().x - a.x, plan.back().y - a.y) > 0.02) {
    EXPECT_LT(std::abs(std::remainder(join - arrive, 2 * M_PI)), 0.35);
  }
  // Independent: brute-force clearance of the controller's execution of this plan.
  EXPECT_GE(bruteSweepClearance(map, start, plan), 0.05 - 0.015);
}

// A 1.2 m dead end, the chair facing its end, the goal 3 m behind it facing the same way: turning
// round needs a 1.72 m circle (tail swing), so forwards there is no way out; backing out is one
// straight reverse piece.
TEST(FootprintSearch, BacksOutOfADeadEndItCannotTurnIn) {
  const OccupancyMap map = carved(7.0, {{0.5, 6.5, 2.9, 4.1}});
  const Pose2D start{5.0, 3.5, 0.0}, goal{2.0, 3.5, 0.0};
  PlannerSettings settings = wheelchair_planner::chairBoxSettings();
  settings.gate.search.time_limit = 2.0;
  settings.gate.search.reverse = false;
  HarmonicPlanner forward_only;
  forward_only.configure(settings, HarmonicPlannerConfig());
  forward_only.setMap(map);
  std::vector<Pose2D> plan;
  Certificate refused;
  EXPECT_FALSE(forward_only.makePlan(start, goal, plan, refused));
  EXPECT_NE(refused.failure_reason.find("forwards only"), std::string::npos)
      << refused.failure_reason;

  settings.gate.search.reverse = true;
  HarmonicPlanner planner;
  planner.configure(settings, HarmonicPlannerConfig());
  planner.setMap(map);
  Certificate cert;
  ASSERT_TRUE(planner.makePlan(start, goal, plan, cert)) << cert.failure_reason;
  EXPECT_EQ(cert.path_stage, "footprint_search");
  EXPECT_GE(cert.footprint_clearance, 0.05);
  // Analytic: 3 m straight back, no cusp (the chair starts by backing up).
  EXPECT_NEAR(cert.reversed_length, 3.0, 0.3);
  EXPECT_EQ(cert.cusps, 0);
  ASSERT_EQ(cert.segment_reverse.size(), 1u);
  EXPECT_TRUE(cert.segment_reverse[0]);
  ASSERT_EQ(cert.segment_clearance.size(), 1u);
  EXPECT_NEAR(cert.segment_clearance[0], cert.footprint_clearance, 1e-9);
  // The chair faces the dead end all the way: every pose's yaw is about 0.
  for (const Pose2D& p : plan) EXPECT_LT(std::abs(std::remainder(p.yaw, 2 * M_PI)), 0.35);
  EXPECT_NEAR(plan.back().x, goal.x, 1e-9);
  // Independent: brute-force clearance of the reverse motion (the body facing +x).
  EXPECT_GE(bruteSweepClearance(map, start, plan), 0.05 - 0.015);
}

// The same dead end, the goal facing the other way: the body's diagonal (1.26 m) is longer than
// the corridor is wide, so no multi-point turn fits either.
TEST(FootprintSearch, RefusesATurnTheBodyCannotMakeAndSaysWhere) {
  const OccupancyMap map = carved(7.0, {{0.5, 6.5, 2.9, 4.1}});
  HarmonicPlanner planner;
  PlannerSettings settings = wheelchair_planner::chairBoxSettings();
  settings.gate.search.time_limit = 0.5;
  planner.configure(settings, HarmonicPlannerConfig());
  planner.setMap(map);
  std::vector<Pose2D> plan;
  Certificate cert;
  EXPECT_FALSE(planner.makePlan({5.0, 3.5, 0.0}, {2.0, 3.5, M_PI}, plan, cert));
  EXPECT_TRUE(plan.empty());
  EXPECT_NE(cert.failure_reason.find("would hit"), std::string::npos) << cert.failure_reason;
  EXPECT_NE(cert.failure_reason.find("no footprint-feasible path"), std::string::npos)
      << cert.failure_reason;
  EXPECT_NE(cert.failure_reason.find("forwards and in reverse"), std::string::npos)
      << cert.failure_reason;
}

// Issue 24: one setting stopped at 3000 expansions with most of the time budget left. The
// budget is one (time and expansions) and is used to the end.
TEST(FootprintSearch, UsesItsWholeExpansionBudget) {
  // A 6 m room and off it an L of 0.85 m passages: the axle disc takes the corner, the body
  // (1.10 x 0.62 m, 5 cm clearance: a rectangle longer than 2 (0.75 sqrt 2 - 0.62) = 0.88 m
  // cannot take it by any motion) never does; the room's lattice is far larger than the budget.
  const OccupancyMap map =
      carved(7.0, {{0.5, 6.5, 0.5, 5.0}, {3.1, 3.95, 4.9, 6.1}, {3.1, 6.5, 5.25, 6.1}});
  HarmonicPlanner planner;
  PlannerSettings settings = wheelchair_planner::chairBoxSettings();
  settings.gate.search.time_limit = 60.0;
  settings.gate.search.max_expansions = 4500;
  settings.gate.search.attempts.resize(1);
  planner.configure(settings, HarmonicPlannerConfig());
  planner.setMap(map);
  std::vector<Pose2D> plan;
  Certificate cert;
  EXPECT_FALSE(planner.makePlan({2.0, 2.0, 0.0}, {5.8, 5.675, 0.0}, plan, cert));
  EXPECT_EQ(cert.search_expansions, 4500) << cert.failure_reason;
  EXPECT_GT(cert.search_expansions, settings.gate.search.attempt_expansions);
  EXPECT_NE(cert.failure_reason.find("budget of 4500 expansions is spent"), std::string::npos)
      << cert.failure_reason;
}
