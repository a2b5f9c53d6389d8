// The footprint gate with the harmonic plugin: the footprint search repairs the harmonic path in
// an L-corner (its sweep verified independently by a brute-force box-vs-cell test with the
// controller's own smoothing) and refuses a turn the body cannot make, saying where.
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

TEST(FootprintSearch, RefusesATurnTheBodyCannotMakeAndSaysWhere) {
  // A 1.2 m dead end, the chair facing its end, the goal behind it: turning needs a 1.72 m
  // circle (tail swing) and the chair cannot reverse.
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
}
