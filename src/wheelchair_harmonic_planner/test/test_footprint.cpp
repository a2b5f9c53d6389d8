// The footprint gate: the checker against analytic geometry, the executed sweep against the
// disc model in an L-corner, the footprint search's repair (its sweep verified here by a
// brute-force box-vs-cell test with the controller's own smoothing) and a refused turn.
#include <wheelchair_controller/smooth_path.h>
#include <wheelchair_harmonic_planner/footprint.h>
#include <wheelchair_harmonic_planner/footprint_search.h>
#include <wheelchair_harmonic_planner/harmonic_planner.h>
#include <wheelchair_harmonic_planner/ompl_planner.h>
#include <wheelchair_harmonic_planner/path_metrics.h>
#include <wheelchair_harmonic_planner/sweep.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace wheelchair_harmonic_planner;
using wheelchair_core::OccupancyMap;

#ifndef LCORNER_W
#define LCORNER_W 1.2
#endif

namespace {

// The chair of chair.yaml: front-wheel drive, body 0.30 m ahead of and 0.80 m behind the axle.
const std::vector<Vertex> kChair{{0.30, 0.31}, {-0.80, 0.31}, {-0.80, -0.31}, {0.30, -0.31}};
const std::string kChairText = "0.30,0.31;-0.80,0.31;-0.80,-0.31;0.30,-0.31";

/// All occupied, then the given world rectangles [x0, x1] x [y0, y1] carved free.
OccupancyMap carved(double size, const std::vector<std::array<double, 4>>& free_boxes) {
  OccupancyMap map;
  map.resolution = 0.05;
  map.width = map.height = static_cast<int>(std::lround(size / map.resolution));
  map.data.assign(static_cast<size_t>(map.width) * map.height, wheelchair_core::kOccupied);
  for (int iy = 0; iy < map.height; ++iy) {
    for (int ix = 0; ix < map.width; ++ix) {
      double x, y;
      map.cellToWorld(ix, iy, x, y);
      for (const auto& b : free_boxes)
        if (x > b[0] && x < b[1] && y > b[2] && y < b[3]) map.at(ix, iy) = wheelchair_core::kFree;
    }
  }
  return map;
}

/// Signed distance from a map point to the chair's box at `pose` (exact box SDF).
double boxDistance(const Pose2D& pose, double x, double y) {
  const double c = std::cos(pose.yaw), s = std::sin(pose.yaw);
  const double u = c * (x - pose.x) + s * (y - pose.y), v = -s * (x - pose.x) + c * (y - pose.y);
  const double qx = std::abs(u - (-0.25)) - 0.55, qy = std::abs(v) - 0.31;
  return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
}

/// Brute force: the smallest distance from the box at `pose` to any occupied cell square
/// (each cell sampled 6 x 6 on its area, edges included).
double bruteClearance(const OccupancyMap& map, const Pose2D& pose) {
  double best = 1e9;
  int cx, cy;
  map.worldToCell(pose.x, pose.y, cx, cy);
  const int reach = static_cast<int>(1.2 / map.resolution);
  for (int iy = cy - reach; iy <= cy + reach; ++iy) {
    for (int ix = cx - reach; ix <= cx + reach; ++ix) {
      if (map.inBounds(ix, iy) && map.at(ix, iy) < 50) continue;
      for (int a = 0; a <= 5; ++a) {
        for (int b = 0; b <= 5; ++b) {
          const double x = map.origin_x + (ix + a / 5.0) * map.resolution;
          const double y = map.origin_y + (iy + b / 5.0) * map.resolution;
          best = std::min(best, boxDistance(pose, x, y));
        }
      }
    }
  }
  return best;
}

/// The controller's execution of `plan` from `start`, rebuilt here from its SmoothPath: start
/// rotation, the smoothed path every 1 cm with its tangent, the goal rotation; brute-force
/// clearance of every pose.
double bruteSweepClearance(const OccupancyMap& map, const Pose2D& start,
                           const std::vector<Pose2D>& plan) {
  std::vector<wheelchair_controller::Pose2> poses;
  for (const Pose2D& p : plan) poses.emplace_back(p.x, p.y, p.yaw);
  const wheelchair_controller::SmoothPath path(poses);
  std::vector<Pose2D> body;
  const auto rotate = [&](double x, double y, double a0, double a1) {
    const double d = std::remainder(a1 - a0, 2.0 * M_PI);
    for (int k = 0; k <= 60; ++k) body.push_back({x, y, a0 + d * k / 60.0});
  };
  rotate(start.x, start.y, start.yaw, path.at(0.0).heading);
  for (double s = 0.0; s <= path.length(); s += 0.01) {
    const auto q = path.at(s);
    body.push_back({q.position.x(), q.position.y(), q.heading});
  }
  const auto end = path.at(path.length());
  rotate(end.position.x(), end.position.y(), end.heading, plan.back().yaw);
  double best = 1e9;
  for (const Pose2D& p : body) best = std::min(best, bruteClearance(map, p));
  return best;
}

// An L of two corridors of width w: east along y in [0.5, 0.5 + w], then north along
// x in [6.5 - w, 6.5].
OccupancyMap lCorner(double w) {
  return carved(7.0, {{0.5, 6.5, 0.5, 0.5 + w}, {6.5 - w, 6.5, 0.5, 6.5}});
}

}  // namespace

TEST(FootprintChecker, BoxAtAKnownDistanceFromAWallAxisAlignedAndRotated) {
  // Free below y = 4.0 (the wall's cells start there), wall above.
  const OccupancyMap map = carved(6.0, {{0.1, 5.9, 0.1, 4.0}});
  const ConfigSpace cs(map, ConfigSpaceParams());
  const FootprintChecker checker(cs, kChair);
  EXPECT_NEAR(checker.circumscribedRadius(), std::hypot(0.80, 0.31), 1e-12);
  EXPECT_NEAR(checker.inscribedRadius(), 0.30, 1e-12);
  const double wall = 4.0;
  for (const double yaw_deg : {0.0, 30.0, 90.0, 135.0, -90.0, 180.0}) {
    const double yaw = yaw_deg * M_PI / 180.0;
    const Pose2D pose{3.0, 2.9, yaw};
    // Analytic: the wall minus the highest vertex of the rotated box.
    double top = -1e9;
    for (const Vertex& v : kChair)
      top = std::max(top, pose.y + std::sin(yaw) * v[0] + std::cos(yaw) * v[1]);
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
  const FootprintChecker checker(cs, kChair);
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
  const FootprintChecker checker(cs, kChair);
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
  const FootprintChecker cchecker(ccs, kChair);
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
  const FootprintChecker checker(cs, kChair);
  // The corridors' centre lines with a right-angle corner (what a disc-model planner returns).
  std::vector<Pose2D> plan;
  for (double x = 1.5; x < 5.9; x += 0.05) plan.push_back({x, 1.1, 0.0});
  for (double y = 1.1; y <= 4.0; y += 0.05) plan.push_back({5.9, y, 0.0});
  assignHeadings(plan, M_PI / 2);
  ASSERT_TRUE(pathIsCollisionFree(cs, plan)) << "the disc model accepts the centre line";
  const Pose2D start{1.5, 1.1, 0.0};
  const SweepCheck check =
      checkSweep(checker, executedSweep(start, plan), clearanceRule(checker, start, 0.05));
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

TEST(FootprintSearch, RepairsTheHarmonicPathInAnLCornerAndItsSweepHoldsIndependently) {
  const OccupancyMap map = lCorner(LCORNER_W);
  HarmonicPlanner planner;
  planner.initialize("harmonic", map, {{"inscribed_radius", "0.31"}, {"footprint", kChairText}});
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
  planner.initialize(
      "harmonic", map,
      {{"inscribed_radius", "0.31"}, {"footprint", kChairText}, {"footprint_search_time", "0.5"}});
  std::vector<Pose2D> plan;
  Certificate cert;
  EXPECT_FALSE(planner.makePlan({5.0, 3.5, 0.0}, {2.0, 3.5, M_PI}, plan, cert));
  EXPECT_TRUE(plan.empty());
  EXPECT_NE(cert.failure_reason.find("would hit"), std::string::npos) << cert.failure_reason;
  EXPECT_NE(cert.failure_reason.find("no footprint-feasible path"), std::string::npos)
      << cert.failure_reason;
}

TEST(FootprintGate, GatesTheOmplPluginsPlansToo) {
  const OccupancyMap map = lCorner(1.2);
  const Pose2D start{1.5, 1.1, 0.0}, goal{5.9, 5.0, M_PI / 2};
  for (const bool repair : {false, true}) {
    OmplPlanner planner;
    planner.initialize("ompl", map,
                       {{"algorithm", "RRTConnect"},
                        {"seed", "7"},
                        {"footprint", kChairText},
                        {"footprint_repair", repair ? "true" : "false"}});
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
