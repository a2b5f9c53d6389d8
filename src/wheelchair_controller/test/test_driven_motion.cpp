// The motion the controller exports for a path (driven_motion.h: what the planner's footprint
// gate checks) against the motion the tracker really drives: the closed loop on the model (heavier
// rider, rolling resistance, encoders) keeps the chair's body on the exported sweep's poses, and
// the sweep has the phases the tracker goes through.
#include <wheelchair_controller/driven_motion.h>
#include <wheelchair_controller_test/closed_loop_simulation.h>
#include <wheelchair_controller_test/test_paths.h>
#include <wheelchair_core/polygon.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace wc = wheelchair_controller;
namespace wd = wheelchair_description;
using wheelchair_core::Pose2D;

namespace {

wd::ChairParams chair() { return wd::test::shippedChair(); }

wc::PlantConfig mismatchedPlant() { return wc::heavierRiderPlant(chair()); }

/// How far the body at `pose` is from the body at the nearest sweep pose: the largest distance
/// between corresponding footprint vertices [m].
double bodyDistanceToSweep(const Pose2D& pose, const std::vector<wc::SweepPose>& sweep,
                           const wheelchair_core::Polygon& footprint) {
  double best = 1e9;
  for (const wc::SweepPose& s : sweep) {
    double worst = 0.0;
    for (const Eigen::Vector2d& v : footprint)
      worst = std::max(worst, (wheelchair_core::transformPoint(pose, v) -
                               wheelchair_core::transformPoint(s.pose, v))
                                  .norm());
    best = std::min(best, worst);
  }
  return best;
}

bool hasPhase(const std::vector<wc::SweepPose>& sweep, wc::SweepPose::Phase phase) {
  return std::any_of(sweep.begin(), sweep.end(),
                     [&](const wc::SweepPose& s) { return s.phase == phase; });
}

bool entered(const wc::ClosedLoopResult& r, wc::TrackerState state) {
  return std::any_of(r.trace.begin(), r.trace.end(),
                     [&](const wc::TraceSample& s) { return s.state == state; });
}

/// The tracker's first active phase is an in-place alignment (the start rotation; alignments at
/// cusps come later).
bool alignsFirst(const wc::ClosedLoopResult& r) {
  for (const wc::TraceSample& s : r.trace)
    if (s.state != wc::TrackerState::kIdle) return s.state == wc::TrackerState::kAligning;
  return false;
}

struct Case {
  std::string name;
  std::vector<Pose2D> path;
  Pose2D start;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const wc::NamedPath& p : wc::homeTestPaths()) out.push_back({p.name, p.poses, p.poses[0]});
  // Facing away from the path: an in-place rotation first; a goal heading a quarter turn off the
  // path's end: an in-place rotation last.
  const std::vector<Pose2D> straight = wc::PathBuilder({0.0, 0.0, 0.0}).straight(2.0).poses();
  out.push_back({"turned_away_at_the_start", straight, {0.0, 0.0, 2.0}});
  out.push_back({"goal_heading_a_quarter_turn_left",
                 wc::PathBuilder({0.0, 0.0, 0.0}).straight(2.0).posesWithGoalHeading(M_PI / 2),
                 {0.0, 0.0, 0.0}});
  // Reverse pieces and cusps: backing out of a door with a quarter turn, then driving off; a
  // three-point turn; backing up from a start facing away (rotation, then reverse).
  out.push_back({"back_out_and_drive_off",
                 wc::PathBuilder({1.0, 2.0, M_PI / 2})
                     .reverse()
                     .straight(0.5)
                     .arc(1.0, -M_PI / 2)
                     .forward()
                     .straight(2.0)
                     .poses(),
                 {1.0, 2.0, M_PI / 2}});
  out.push_back({"three_point_turn", wc::threePointTurnPath(), {0.0, 0.0, 0.0}});
  out.push_back({"back_up_after_turning",
                 wc::PathBuilder({0.0, 0.0, 0.0}).reverse().straight(1.5).poses(),
                 {0.0, 0.0, 1.5}});
  return out;
}

}  // namespace

TEST(DrivenMotion, TheTrackersBodyStaysOnTheSweepItExports) {
  const wd::ChairParams model = chair();
  for (const Case& c : cases()) {
    const std::vector<wc::SweepPose> sweep = wc::executedSweep(c.start, c.path);
    ASSERT_FALSE(sweep.empty()) << c.name;
    const wc::ClosedLoopResult r =
        wc::simulateClosedLoop(c.path, c.start, model, wc::TrackerConfig{}, mismatchedPlant());
    ASSERT_EQ(r.final_state, wc::TrackerState::kGoalReached) << c.name << ": " << r.reason;
    double worst = 0.0;
    for (const wc::TraceSample& s : r.trace) {
      const Pose2D truth{s.pose.x(), s.pose.y(), s.pose.z()};
      const double d = bodyDistanceToSweep(truth, sweep, model.footprint);
      worst = std::max(worst, d);
    }
    // Measured 1.0-2.8 cm (slalom); the gate keeps 5 cm around the sweep.
    EXPECT_LT(worst, 0.035) << c.name << ": the body left the sweep the gate checked";
    // The phases: a goal rotation in the sweep exactly when the tracker rotates to the goal
    // heading; an in-place rotation at the start when the tracker aligns first.
    EXPECT_EQ(hasPhase(sweep, wc::SweepPose::Phase::kGoalRotation),
              entered(r, wc::TrackerState::kRotatingToGoal))
        << c.name;
    EXPECT_EQ(std::any_of(sweep.begin(), sweep.end(),
                          [](const wc::SweepPose& s) {
                            return s.phase == wc::SweepPose::Phase::kPath &&
                                   s.direction == wheelchair_core::Direction::kReverse;
                          }),
              entered(r, wc::TrackerState::kReversing))
        << c.name << ": reverse in the sweep exactly when the tracker reverses";
    if (alignsFirst(r)) {
      EXPECT_GT(std::count_if(sweep.begin(), sweep.end(),
                              [](const wc::SweepPose& s) {
                                return s.phase == wc::SweepPose::Phase::kStartRotation;
                              }),
                10)
          << c.name;
    }
    RecordProperty(c.name + "_body_distance_m", std::to_string(worst));
  }
}

TEST(DrivenMotion, ARefusedPathHasNoSweep) {
  EXPECT_TRUE(wc::executedSweep({0.0, 0.0, 0.0}, {}).empty());
  EXPECT_TRUE(wc::executedSweep({0.0, 0.0, 0.0}, {{0.0, 0.0, 0.0}, {0.005, 0.0, 0.0}}).empty())
      << "shorter than the controller's minimum path length";
  EXPECT_TRUE(wc::executedSweep({0.0, 0.0, 0.0}, {{0.0, 0.0, 0.0}, {NAN, 0.0, 0.0}}).empty());
  std::string rejection;
  EXPECT_FALSE(wc::drivenPlan({{0.0, 0.0, 0.0}, {0.005, 0.0, 0.0}}, rejection));
  EXPECT_NE(rejection.find("zero-length"), std::string::npos) << rejection;
}

TEST(DrivenMotion, AReversePieceFacesAgainstItsMotionAndTheSweepStopsAtTheCusp) {
  // Back 1 m facing +x, then 1 m forward: the sweep's body faces +x all along (no turn), the
  // reverse poses move towards -x, the forward ones towards +x, and they meet at the cusp.
  const std::vector<Pose2D> path =
      wc::PathBuilder({0.0, 0.0, 0.0}).reverse().straight(1.0).forward().straight(1.0).poses();
  std::string rejection;
  const std::optional<wc::DrivenPlan> plan = wc::drivenPlan(path, rejection);
  ASSERT_TRUE(plan) << rejection;
  ASSERT_EQ(plan->pieces.size(), 2u);
  EXPECT_EQ(plan->cusps(), 1u);
  EXPECT_TRUE(plan->pieces[0].reverse());
  EXPECT_NEAR(std::remainder(plan->pieces[0].startHeading(), 2 * M_PI), 0.0, 1e-6);
  EXPECT_NEAR(std::remainder(plan->pieces[1].startHeading(), 2 * M_PI), 0.0, 1e-6);
  const std::vector<wc::SweepPose> sweep = wc::executedSweep({0.0, 0.0, 0.0}, path);
  ASSERT_FALSE(sweep.empty());
  double min_x = 1e9;
  for (const wc::SweepPose& s : sweep) {
    EXPECT_NEAR(std::remainder(s.pose.yaw, 2 * M_PI), 0.0, 1e-6);
    min_x = std::min(min_x, s.pose.x);
    EXPECT_EQ(s.piece == 0, s.direction == wheelchair_core::Direction::kReverse);
  }
  EXPECT_NEAR(min_x, -1.0, 0.01);
  EXPECT_NEAR(sweep.back().pose.x, 0.0, 0.01);
  EXPECT_FALSE(hasPhase(sweep, wc::SweepPose::Phase::kStartRotation) &&
               sweep.front().pose.yaw != sweep[1].pose.yaw);
}

TEST(DrivenMotion, SweepPosesAreAtMostTheSamplingApart) {
  const std::vector<Pose2D> path =
      wc::PathBuilder({0.0, 0.0, 0.0}).straight(1.0).arc(0.6, M_PI).posesWithGoalHeading(0.0);
  const wc::SweepSampling sampling;
  const std::vector<wc::SweepPose> sweep = wc::executedSweep({0.0, 0.0, -1.0}, path);
  for (size_t i = 1; i < sweep.size(); ++i) {
    const Pose2D& a = sweep[i - 1].pose;
    const Pose2D& b = sweep[i].pose;
    EXPECT_LE(std::hypot(b.x - a.x, b.y - a.y), sampling.max_step + 1e-9) << i;
    EXPECT_LE(std::abs(std::remainder(b.yaw - a.yaw, 2.0 * M_PI)), sampling.max_turn + 1e-9) << i;
  }
  EXPECT_EQ(sweep.front().phase, wc::SweepPose::Phase::kStartRotation);
  EXPECT_DOUBLE_EQ(sweep.front().pose.yaw, -1.0);
  EXPECT_EQ(sweep.back().phase, wc::SweepPose::Phase::kGoalRotation);
  EXPECT_NEAR(std::remainder(sweep.back().pose.yaw, 2.0 * M_PI), 0.0, 1e-9);
}
