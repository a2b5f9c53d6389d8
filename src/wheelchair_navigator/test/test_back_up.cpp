// The back-up recovery's trail (issue 24): the way the chair came, driven back in reverse.
#include <gtest/gtest.h>
#include <wheelchair_core/path_direction.h>
#include <wheelchair_navigator/back_up.h>

#include <cmath>

using namespace wheelchair_navigator;

namespace {
// The chair driving forwards along +x from x0 to x1 at heading 0, a pose every 2 cm.
void driveAlongX(BackUpTrail& trail, double x0, double x1, double y = 0.0) {
  for (double x = x0; x <= x1 + 1e-9; x += 0.02) trail.record({x, y, 0.0});
}
BlockedSituation at(double x, double y, double yaw) {
  BlockedSituation s;
  s.chair = {x, y, yaw};
  s.goal = {x + 3.0, y, 0.0};
  s.blocked = {{x + 0.8, y}};
  return s;
}
}  // namespace

TEST(BackUpTrailTest, TheRouteBackRetracesTheWayItCameInReverseForTheConfiguredDistance) {
  BackUpTrail trail;  // distance 2 m
  driveAlongX(trail, 0.0, 4.0);
  const auto back = trail.route(at(4.0, 0.0, 0.0));
  ASSERT_GE(back.size(), 3u);
  EXPECT_DOUBLE_EQ(back.front().x, 4.0);
  EXPECT_NEAR(back.back().x, 2.0, 1e-6);  // 2 m back along +x
  for (const auto& p : back) {
    EXPECT_NEAR(p.y, 0.0, 1e-9);
    EXPECT_NEAR(p.yaw, 0.0, 1e-9);  // the chair keeps facing the way it came from
  }
  const auto pieces = wheelchair_core::splitAtCusps(back);
  ASSERT_EQ(pieces.size(), 1u) << "the back-up is one reverse piece, no cusp";
  EXPECT_EQ(pieces[0].direction, wheelchair_core::Direction::kReverse);
  EXPECT_NEAR(wheelchair_core::reversedLength(back), 2.0, 1e-6);
}

TEST(BackUpTrailTest, ACurvedApproachIsRetracedThroughItsOwnPoses) {
  BackUpTrail trail;
  // A quarter circle of radius 1.5 m, driven forwards (heading = tangent).
  for (double a = 0.0; a <= M_PI / 2 + 1e-9; a += 0.01)
    trail.record({1.5 * std::sin(a), 1.5 * (1.0 - std::cos(a)), a});
  const Pose2D end{1.5, 1.5, M_PI / 2};
  const auto back = trail.route(at(end.x, end.y, end.yaw));
  ASSERT_GE(back.size(), 3u);
  for (const auto& p : back)  // every pose on the circle the chair drove
    EXPECT_NEAR(std::hypot(p.x, p.y - 1.5), 1.5, 1e-3);
  EXPECT_EQ(wheelchair_core::cuspCount(back), 0u);
  EXPECT_EQ(wheelchair_core::splitAtCusps(back)[0].direction, wheelchair_core::Direction::kReverse);
  EXPECT_NEAR(wheelchair_core::reversedLength(back), 2.0, 0.01);
}

TEST(BackUpTrailTest, AShortTrailIsNoWayOut) {
  BackUpTrail trail;  // min_distance 0.3 m
  driveAlongX(trail, 0.0, 0.2);
  EXPECT_TRUE(trail.route(at(0.2, 0.0, 0.0)).empty());
}

TEST(BackUpTrailTest, ARelocalizationJumpStartsANewTrail) {
  BackUpTrail trail;
  driveAlongX(trail, 0.0, 3.0);
  driveAlongX(trail, 0.0, 1.0, 2.0);  // the pose jumped 2 m sideways, then drove 1 m
  const auto back = trail.route(at(1.0, 2.0, 0.0));
  ASSERT_FALSE(back.empty());
  EXPECT_NEAR(back.back().x, 0.0, 1e-6) << "backed beyond the start of the new trail";
  for (const auto& p : back) EXPECT_NEAR(p.y, 2.0, 1e-9);
}

TEST(BackUpTrailTest, OnlyTheStretchDrivenForwardsSinceTheChairLastBackedIsKept) {
  BackUpTrail trail;
  driveAlongX(trail, 0.0, 3.0);
  for (double x = 3.0; x >= 2.0 - 1e-9; x -= 0.02) trail.record({x, 0.0, 0.0});  // backed 1 m
  trail.record({2.0, 0.0, M_PI / 2});  // turned on the spot
  for (double y = 0.0; y <= 0.8 + 1e-9; y += 0.02) trail.record({2.0, y, M_PI / 2});
  EXPECT_NEAR(trail.length(), 0.8, 0.06);  // within one recorded step
  const auto back = trail.route(at(2.0, 0.8, M_PI / 2));
  ASSERT_FALSE(back.empty());
  EXPECT_NEAR(back.back().y, 0.0, 0.06);
  EXPECT_GE(back.back().x, 2.0 - 1e-9) << "backed into the stretch it had backed along";
  EXPECT_EQ(wheelchair_core::cuspCount(back), 0u);
}

TEST(BackUpTrailTest, NoRouteBackWhenTheChairIsFarFromItsTrail) {
  BackUpTrail trail;
  driveAlongX(trail, 0.0, 3.0);
  EXPECT_TRUE(trail.route(at(3.0, 1.5, 0.0)).empty());
}

TEST(BackUpTrailTest, TheTrailKeepsOnlyTheLastMetres) {
  BackUpTrail trail(BackUpConfig{2.0, 0.3, 0.05, 0.5, 3.0});
  driveAlongX(trail, 0.0, 10.0);
  EXPECT_LE(trail.length(), 3.0 + 0.1);  // within one recorded step
  EXPECT_GE(trail.length(), 3.0);
}

// ---- the rule: back up only where the trail's end has a route the chair's pose lacks --------

namespace {
// A planner that knows routes from the places in `from` (and, for nullopt, `from_chair`).
struct FakePlanner {
  bool from_chair = false;
  bool from_trail_end = false;
  std::vector<std::optional<Pose2D>> asked;
  BackUpRecovery::RouteQuery query() {
    return [this](const std::optional<Pose2D>& start, const Pose2D&, std::string& detail) {
      asked.push_back(start);
      const bool route = start ? from_trail_end : from_chair;
      detail = route ? "" : "no route";
      return route;
    };
  }
};
void driveAlongX(BackUpRecovery& recovery, double x0, double x1) {
  for (double x = x0; x <= x1 + 1e-9; x += 0.02) recovery.record({x, 0.0, 0.0});
}
}  // namespace

TEST(BackUpRuleTest, BacksUpOnlyWhenTheTrailsEndHasARouteAndTheChairsPoseHasNone) {
  EXPECT_TRUE(backUpHelps(false, true));
  EXPECT_FALSE(backUpHelps(false, false));  // the only doorway blocked: backing cannot help
  EXPECT_FALSE(backUpHelps(true, true));    // a way from here: drive that
  EXPECT_FALSE(backUpHelps(true, false));
}

TEST(BackUpRuleTest, ADeadEndWithAWayOnBehindGetsTheTrailBackOnTheNextAskFromTheSamePlace) {
  FakePlanner planner;
  planner.from_trail_end = true;
  BackUpRecovery recovery(BackUpConfig(), planner.query());
  driveAlongX(recovery, 0.0, 4.0);
  EXPECT_TRUE(recovery.offer(at(4.0, 0.0, 0.0)).empty()) << "the first ask only starts the check";
  recovery.waitIdle();
  ASSERT_EQ(planner.asked.size(), 2u);
  ASSERT_TRUE(planner.asked[0].has_value()) << "first from the trail's end";
  EXPECT_NEAR(planner.asked[0]->x, 2.0, 1e-6);  // 2 m back along the way it came
  EXPECT_FALSE(planner.asked[1].has_value()) << "then from the chair's own pose";
  const auto back = recovery.offer(at(4.02, 0.0, 0.0));  // the chair stands where it was
  ASSERT_GE(back.size(), 3u);
  EXPECT_NEAR(back.front().x, 4.02, 1e-9);  // from where it stands now, 2 m back
  EXPECT_NEAR(back.back().x, 2.02, 1e-6);
  EXPECT_NEAR(wheelchair_core::reversedLength(back), 2.0, 1e-6);
}

TEST(BackUpRuleTest, TheOnlyWayBlockedEverywhereGetsNoBackUpAndAsksThePlannerOnce) {
  FakePlanner planner;  // no route from anywhere
  BackUpRecovery recovery(BackUpConfig(), planner.query());
  driveAlongX(recovery, 0.0, 4.0);
  for (int ask = 0; ask < 4; ++ask) {
    EXPECT_TRUE(recovery.offer(at(4.0, 0.0, 0.0)).empty());
    recovery.waitIdle();
  }
  EXPECT_EQ(planner.asked.size(), 1u) << "the verdict holds while the chair stands there";
}

TEST(BackUpRuleTest, AWayFromWhereTheChairStandsGetsNoBackUp) {
  FakePlanner planner;
  planner.from_chair = planner.from_trail_end = true;
  BackUpRecovery recovery(BackUpConfig(), planner.query());
  driveAlongX(recovery, 0.0, 4.0);
  EXPECT_TRUE(recovery.offer(at(4.0, 0.0, 0.0)).empty());
  recovery.waitIdle();
  EXPECT_TRUE(recovery.offer(at(4.0, 0.0, 0.0)).empty());
}

TEST(BackUpRuleTest, AVerdictForOnePlaceIsNotUsedElsewhereNorWithoutATrail) {
  FakePlanner planner;
  planner.from_trail_end = true;
  BackUpRecovery recovery(BackUpConfig(), planner.query());
  EXPECT_TRUE(recovery.offer(at(4.0, 0.0, 0.0)).empty());  // no trail yet: nothing asked
  recovery.waitIdle();
  EXPECT_TRUE(planner.asked.empty());
  driveAlongX(recovery, 0.0, 4.0);
  EXPECT_TRUE(recovery.offer(at(4.0, 0.0, 0.0)).empty());
  recovery.waitIdle();
  driveAlongX(recovery, 4.0, 5.0);  // it drove on 1 m: the verdict was for (4, 0)
  EXPECT_TRUE(recovery.offer(at(5.0, 0.0, 0.0)).empty()) << "a new check, not the old verdict";
  recovery.waitIdle();
  EXPECT_EQ(planner.asked.size(), 4u);
  EXPECT_NEAR(planner.asked[2]->x, 3.0, 1e-6);
  EXPECT_FALSE(recovery.offer(at(5.0, 0.0, 0.0)).empty());
}

TEST(BackUpTrailTest, APoseCorrectedSidewaysAtRestStillBacksStraightAlongTheTrail) {
  BackUpTrail trail;
  driveAlongX(trail, 0.0, 4.0);
  // Standing, the localizer moved the pose 6 cm sideways: the newest trail poses lie beside it.
  const auto back = trail.route(at(4.0, 0.06, 0.0));
  ASSERT_GE(back.size(), 2u);
  const double first = std::atan2(back[1].y - back[0].y, back[1].x - back[0].x);
  EXPECT_LT(std::abs(wheelchair_core::angleDifference(first, M_PI)), 0.15)
      << "the first step goes straight back, not sideways";
  EXPECT_NEAR(back.back().x, 2.0, 0.01);
}
