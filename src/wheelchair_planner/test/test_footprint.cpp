// The footprint gate's parts: the checker against analytic geometry, the executed sweep against
// the disc model in an L-corner (and an independent brute-force box-vs-cell check with the
// controller's own smoothing), and the gate checking the motion the controller exports. The
// gate with each plugin and its repair search: the plugins' own tests.
#include <wheelchair_controller/driven_motion.h>
#include <wheelchair_planner/footprint_checker.h>
#include <wheelchair_planner/footprint_gate.h>
#include <wheelchair_planner/path_metrics.h>
#include <wheelchair_planner/sweep_check.h>
#include <wheelchair_planner_test/footprint_worlds.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace wheelchair_planner;
using wheelchair_core::OccupancyMap;

TEST(FootprintChecker, BoxAtAKnownDistanceFromAWallAxisAlignedAndRotated) {
  // Free below y = 4.0 (the wall's cells start there), wall above.
  const OccupancyMap map = carved(6.0, {{0.1, 5.9, 0.1, 4.0}});
  const ConfigSpace cs(map, ConfigSpaceParams());
  const FootprintChecker checker(cs, chairBox());
  EXPECT_NEAR(checker.circumscribedRadius(), std::hypot(0.80, 0.31), 1e-12);
  EXPECT_NEAR(checker.inscribedRadius(), 0.30, 1e-12);
  const double wall = 4.0;
  for (const double yaw_deg : {0.0, 30.0, 90.0, 135.0, -90.0, 180.0}) {
    const double yaw = yaw_deg * M_PI / 180.0;
    const Pose2D pose{3.0, 2.9, yaw};
    // Analytic: the wall minus the highest vertex of the rotated box.
    double top = -1e9;
    for (const Eigen::Vector2d& v : chairBox())
      top = std::max(top, pose.y + std::sin(yaw) * v.x() + std::cos(yaw) * v.y());
    const FootprintContact c = checker.clearance(pose);
    EXPECT_NEAR(c.clearance, wall - top, 0.013) << "yaw " << yaw_deg;
    EXPECT_NEAR(c.y, top, 0.03) << "the contact is on the top of the body, yaw " << yaw_deg;
  }
  // Tail up (yaw -90 deg): the rear is 0.80 m from the axle: at 2.9 it reaches 3.7.
  EXPECT_NEAR(checker.clearance({3.0, 2.9, -M_PI / 2}).clearance, 0.30, 0.013);
  // Early stop: the value is below the threshold.
  EXPECT_LT(checker.clearance({3.0, 3.5, -M_PI / 2}, 0.05).clearance, 0.05);
}

TEST(FootprintChecker, AnObstacleCellInsideTheBodyIsACollision) {
  OccupancyMap map = carved(6.0, {{0.1, 5.9, 0.1, 5.9}});
  int ix, iy;
  ASSERT_TRUE(map.worldToCell(2.6, 3.0, ix, iy));  // 0.4 m behind the axle, under the seat
  map.at(ix, iy) = wheelchair_core::kOccupied;
  const ConfigSpace cs(map, ConfigSpaceParams());
  const FootprintChecker checker(cs, chairBox());
  EXPECT_LT(checker.clearance({3.0, 3.0, 0.0}).clearance, 0.0);
  // Facing the other way the cell is ahead, beyond the 0.30 m front: the gap from the front
  // (x = 2.70) to the cell's right edge.
  const double cell_edge = map.origin_x + (ix + 1) * map.resolution;
  EXPECT_NEAR(checker.clearance({3.0, 3.0, M_PI}).clearance, 2.70 - cell_edge, 0.013);
}

// The cheap early answer of the sweep check (a cover of the body by four discs) is a lower
// bound of the clearance: against the full computation and the brute-force box-vs-cell distance
// at random poses
// among random blocks, and in a 1.8 m corridor, where it answers although the one disc
// enclosing the body (0.86 m radius) is not clear.
TEST(FootprintChecker, DiscCoverGivesALowerBoundOfTheClearance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(0.5, 7.5), angle(-M_PI, M_PI);
  OccupancyMap map = carved(8.0, {{0.1, 7.9, 0.1, 7.9}});
  for (int b = 0; b < 12; ++b) {
    int ix, iy;
    map.worldToCell(coord(rng), coord(rng), ix, iy);
    for (int dy = 0; dy < 4; ++dy)
      for (int dx = 0; dx < 4; ++dx) map.at(ix + dx, iy + dy) = wheelchair_core::kOccupied;
  }
  const ConfigSpace cs(map, ConfigSpaceParams());
  const FootprintChecker checker(cs, chairBox());
  int early = 0;
  for (int i = 0; i < 300; ++i) {
    const Pose2D pose{coord(rng), coord(rng), angle(rng)};
    const FootprintContact bound = checker.clearance(pose, -1e9, 0.30);
    if (bound.clearance < 0.30) continue;  // not answered early: the full computation
    ++early;
    // Below the checker's full answer, and below the true distance up to the checker's stated
    // error (1.3 cm: to a cell's corner the distance field is up to (sqrt(2) - 1) / 2 cell =
    // 1.04 cm too large, plus its bilinear interpolation).
    EXPECT_LE(bound.clearance, checker.clearance(pose).clearance + 1e-9) << pose.x << " " << pose.y;
    EXPECT_LE(bound.clearance, bruteClearance(map, pose) + 0.013) << pose.x << " " << pose.y;
  }
  EXPECT_GT(early, 20);
  const OccupancyMap corridor = carved(6.0, {{0.1, 5.9, 2.0, 3.8}});
  const ConfigSpace ccs(corridor, ConfigSpaceParams());
  const FootprintChecker cchecker(ccs, chairBox());
  for (const double yaw : {0.0, 0.3, M_PI}) {
    const Pose2D pose{3.0, 2.9, yaw};
    const double full = cchecker.clearance(pose).clearance;
    const double quick = cchecker.clearance(pose, -1e9, 0.30).clearance;
    EXPECT_GE(quick, 0.30) << "yaw " << yaw;
    EXPECT_LT(quick, full - 0.02) << "a bound, not the full computation, yaw " << yaw;
    EXPECT_LE(quick, bruteClearance(corridor, pose)) << "yaw " << yaw;
  }
}

TEST(Sweep, DetectsTheTailSwingInAnLCornerThatTheDiscModelAccepts) {
  const OccupancyMap map = lCorner(1.2);
  const ConfigSpace cs(map, ConfigSpaceParams());
  const FootprintChecker checker(cs, chairBox());
  // The corridors' centre lines with a right-angle corner (what a disc-model planner returns).
  std::vector<Pose2D> plan;
  for (double x = 1.5; x < 5.9; x += 0.05) plan.push_back({x, 1.1, 0.0});
  for (double y = 1.1; y <= 4.0; y += 0.05) plan.push_back({5.9, y, 0.0});
  assignHeadings(plan, M_PI / 2);
  ASSERT_TRUE(pathIsCollisionFree(cs, plan)) << "the disc model accepts the centre line";
  const Pose2D start{1.5, 1.1, 0.0};
  const SweepCheck check =
      checkSweep(checker, SweepModel().sweep(start, plan), clearanceRule(checker, start, 0.05));
  EXPECT_FALSE(check.ok);
  EXPECT_LT(check.min_clearance, 0.0) << "the body hits a wall";
  // Independent: the brute-force box-vs-cells clearance of the same motion is negative too.
  EXPECT_LT(bruteSweepClearance(map, start, plan), 0.0);
  // It is the tail: the contact lies behind the axle in the body frame.
  const Pose2D& p = check.worst_pose;
  const double u =
      std::cos(p.yaw) * (check.contact.x - p.x) + std::sin(p.yaw) * (check.contact.y - p.y);
  EXPECT_LT(u, -0.3) << "contact at (" << check.contact.x << ", " << check.contact.y << ")";
  EXPECT_NE(check.reason.find("would hit"), std::string::npos) << check.reason;
}

// The gate checks exactly the motion the controller exports for the plan (the controller's
// smoothing, phases and tolerances: wheelchair_controller::executedSweep), pose for pose.
TEST(FootprintGate, ChecksTheMotionTheControllerExports) {
  const OccupancyMap map = carved(8.0, {{0.1, 7.9, 0.1, 7.9}});
  const ConfigSpace cs(map, ConfigSpaceParams());
  const FootprintChecker checker(cs, chairBox());
  std::vector<Pose2D> plan;
  for (double x = 2.0; x < 6.0; x += 0.05) plan.push_back({x, 4.0 + 0.3 * std::sin(x), 0.0});
  assignHeadings(plan, M_PI / 2);  // a goal heading that needs a final rotation
  const Pose2D start{2.0, 4.0 + 0.3 * std::sin(2.0), -1.0};  // and a start rotation
  const std::vector<SweepPose> driven = wheelchair_controller::executedSweep(start, plan);
  ASSERT_FALSE(driven.empty());
  FootprintGateParams gate;
  Certificate cert;
  std::vector<Pose2D> gated = plan;
  ASSERT_TRUE(enforceFootprint(checker, gate, start, plan.back(), gated, cert))
      << cert.failure_reason;
  EXPECT_EQ(cert.sweep_poses, static_cast<int>(driven.size()));
  EXPECT_EQ(gated.size(), plan.size()) << "the first stage's plan passes as it is";
  const SweepCheck check = checkSweep(checker, driven, clearanceRule(checker, start, 0.05));
  EXPECT_DOUBLE_EQ(cert.footprint_clearance, check.min_clearance);
  // A controller that rotates to the goal heading only when off by more than a quarter turn
  // drives another motion, and the gate follows it.
  gate.sweep.controller.goal_heading_tolerance = 2.0;
  Certificate lenient;
  ASSERT_TRUE(enforceFootprint(checker, gate, start, plan.back(), gated, lenient));
  EXPECT_LT(lenient.sweep_poses, cert.sweep_poses);
  EXPECT_EQ(lenient.sweep_poses,
            static_cast<int>(
                wheelchair_controller::executedSweep(start, plan, gate.sweep.controller).size()));
}
