// A pause in the control steps (the process stopped or starved): the clock of the steps given
// to the tracker jumps while the chair, its motors braked by their watchdog, slows down. A
// short pause: brake to rest, the reference re-timed from rest where the chair stands, the
// drive goes on to the goal; a hang (longer than hang_timeout, or one pause too many on a
// path): a controlled stop.
#include <wheelchair_controller/path_tracker.h>
#include <wheelchair_controller/start_offset.h>
#include <wheelchair_controller_test/axle_pose.h>
#include <wheelchair_controller_test/test_paths.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace wc = wheelchair_controller;
namespace wd = wheelchair_description;

namespace {

constexpr double kDt = 0.02;  // [s] the control period (50 Hz)

struct PausedRun {
  wc::TrackerOutput last;
  std::vector<std::string> reasons;  ///< every distinct non-empty reason, in order
  bool aborted = false;
  double speed_before = 0.0;     ///< [m/s] at the first pause
  double min_speed_after = 1e9;  ///< [m/s] after the first pause, before the goal
  double max_accel_after = 0.0;  ///< [m/s^2] |dv/dt| of the axle centre after the pause's end
  double rest_travel = 0.0;      ///< [m] along x from the first pause's end to its rest
  double final_x = 0.0;
};

/// Drives a 6 m straight on the model; at each time of `pauses` the steps stop for the paired
/// duration: meanwhile the motors brake the wheels (watchdog) at 1.5 m/s^2.
PausedRun drive(const wc::TrackerConfig& config,
                const std::vector<std::pair<double, double>>& pauses, double max_time = 40.0) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, config);
  EXPECT_EQ(tracker.setPath(wc::PathBuilder({0.0, 0.0, 0.0}).straight(6.0).poses()), "");
  wd::State x = wd::stateAtAxlePose(0.0, 0.0, 0.0, p);
  PausedRun r;
  double t = 0.0, prev_v = 0.0, first_pause_end = -1.0;
  size_t next = 0;
  bool resting = false;
  while (t < max_time) {
    if (next < pauses.size() && t >= pauses[next].first) {  // the pause: no steps, motor brake
      if (next == 0) r.speed_before = wd::bodyVelocity(x.tail<2>(), p)(0);
      for (double s = 0.0; s < pauses[next].second - kDt; s += 1e-3) {
        const double v = wd::bodyVelocity(x.tail<2>(), p)(0);
        const double slowed = std::max(0.0, v - 1.5e-3);
        x.tail<2>() = wd::wheelSpeeds(slowed, 0.0, p);
        x.head<5>() = wd::integrateRK4(x, Eigen::Vector2d::Zero(), 1e-3, p).head<5>();
      }
      t += pauses[next].second - kDt;  // the steps before and after lie `second` apart
      if (next == 0) first_pause_end = t, r.rest_travel = -wc::axlePose2D(x, p).x;
      ++next;
    }
    r.last = tracker.update(t, wc::PoseMeasurement{t, wc::axlePose2D(x, p)}, {t, x.tail<2>()});
    if (!r.last.reason.empty() && (r.reasons.empty() || r.reasons.back() != r.last.reason))
      r.reasons.push_back(r.last.reason);
    if (r.last.state == wc::TrackerState::kAborted) r.aborted = true;
    if (r.last.state == wc::TrackerState::kAborted ||
        r.last.state == wc::TrackerState::kGoalReached)
      break;
    const double v = wd::bodyVelocity(x.tail<2>(), p)(0);
    if (first_pause_end >= 0.0) {
      r.min_speed_after = std::min(r.min_speed_after, v);
      if (t > first_pause_end + kDt)
        r.max_accel_after = std::max(r.max_accel_after, std::abs(v - prev_v) / kDt);
      if (!resting && v < 0.01) resting = true, r.rest_travel += wc::axlePose2D(x, p).x;
    }
    prev_v = v;
    if (r.last.command.brake) {
      x.tail<2>().setZero();
    } else {
      for (int i = 0; i < 20; ++i) x = wd::integrateRK4(x, r.last.command.torque, 1e-3, p);
    }
    t += kDt;
  }
  r.final_x = wc::axlePose2D(x, p).x;
  return r;
}

bool anyReasonHas(const PausedRun& r, const std::string& part) {
  for (const std::string& reason : r.reasons)
    if (reason.find(part) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST(Pause, aShortPauseWhileCruisingBrakesToRestThenTheDriveGoesOnToTheGoal) {
  const PausedRun r = drive(wc::TrackerConfig{}, {{3.0, 0.3}});
  EXPECT_GT(r.speed_before, 0.5) << "the pause must hit a moving chair";
  EXPECT_EQ(r.last.state, wc::TrackerState::kGoalReached) << r.last.reason;
  EXPECT_FALSE(r.aborted);
  EXPECT_TRUE(anyReasonHas(r, "restarting from rest: control steps paused for 0.30 s"))
      << (r.reasons.empty() ? "no reason" : r.reasons.front());
  EXPECT_LT(r.min_speed_after, 0.01) << "the chair came to rest before going on";
  // The brake from ~0.45 m/s after the motor brake and the restart from rest: within the
  // path's comfort acceleration (0.5 m/s^2) and the feedback's share (no jolt, no jump).
  EXPECT_LT(r.max_accel_after, 0.5 * 1.3);
  EXPECT_GT(r.rest_travel, 0.01) << "braked smoothly, not at once";
  EXPECT_NEAR(r.final_x, 6.0, 0.1) << "at the path's end";
}

TEST(Pause, twoShortPausesOnOnePathAreEachRestartedFromRest) {
  const PausedRun r = drive(wc::TrackerConfig{}, {{2.5, 0.2}, {7.0, 0.25}});
  EXPECT_EQ(r.last.state, wc::TrackerState::kGoalReached) << r.last.reason;
  EXPECT_TRUE(anyReasonHas(r, "paused for 0.20 s"));
  EXPECT_TRUE(anyReasonHas(r, "paused for 0.25 s"));
}

TEST(Pause, aPauseLongerThanTheHangTimeoutEndsTheDriveInAControlledStop) {
  const PausedRun r = drive(wc::TrackerConfig{}, {{3.0, 1.5}});
  EXPECT_EQ(r.last.state, wc::TrackerState::kAborted);
  EXPECT_EQ(r.last.reason, "control steps paused for 1.50 s");
  EXPECT_TRUE(r.last.command.brake);
  EXPECT_LT(r.final_x, 6.0 - 1.0) << "the drive did not go on";
}

TEST(Pause, onePauseMoreThanMaxGapRestartsOnOnePathEndsTheDriveInAControlledStop) {
  wc::TrackerConfig config;
  config.max_gap_restarts = 1;
  const PausedRun r = drive(config, {{2.5, 0.2}, {7.0, 0.2}});
  EXPECT_EQ(r.last.state, wc::TrackerState::kAborted);
  EXPECT_NE(r.last.reason.find("paused for 0.20 s (1 restarts from rest on this path before)"),
            std::string::npos)
      << r.last.reason;
  EXPECT_TRUE(anyReasonHas(r, "restarting from rest")) << "the first pause was restarted";
}

TEST(Pause, aPauseAtRestBeforeAnyPathChangesNothing) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, wc::TrackerConfig{});
  tracker.update(0.0, wc::PoseMeasurement{0.0, {0, 0, 0}}, {0.0, {0, 0}});
  const wc::TrackerOutput out =
      tracker.update(5.0, wc::PoseMeasurement{5.0, {0, 0, 0}}, {5.0, {0, 0}});
  EXPECT_EQ(out.state, wc::TrackerState::kIdle);
  EXPECT_EQ(out.reason, "");
  EXPECT_TRUE(out.command.brake);
}

TEST(RestartFromRest, theReferenceStartsAtRestOnTheBaseAndEndsWhereTheBaseEnds) {
  const wd::ChairParams p = wd::test::shippedChair();
  const wc::TrackerConfig config;
  const wc::PreparedPath prepared = wc::preparePath(
      wc::PathBuilder({0.0, 0.0, 0.0}).straight(2.0).arc(1.5, M_PI / 2).poses(), p, config, 0.0);
  ASSERT_TRUE(prepared.rejection.empty()) << prepared.rejection;
  const std::shared_ptr<const wc::OutputTrajectory> base = prepared.trajectories.front();
  const double t0 = 2.5, speed = base->at(t0).velocity.norm();
  ASSERT_GT(speed, 0.3) << "mid-path, moving";
  const double ramp = wc::restartRampTime(speed, config.path_limits.longitudinal);
  const wc::RestartFromRestTrajectory restart(base, t0, ramp);
  EXPECT_LT((restart.at(0.0).position - base->at(t0).position).norm(), 1e-9);
  EXPECT_LT(restart.at(0.0).velocity.norm(), 1e-9);
  EXPECT_LT(restart.at(0.0).acceleration.norm(), 1e-9);
  EXPECT_NEAR(restart.duration(), base->duration() - t0 + ramp / 2, 1e-9);
  EXPECT_LT((restart.at(restart.duration()).position - base->at(base->duration()).position).norm(),
            1e-6);
  // Velocity continuous and the warp's acceleration within the comfort limit (+ the base's own).
  double max_accel = 0.0, max_step = 0.0;
  for (double t = 0.0; t < restart.duration(); t += 0.01) {
    max_accel = std::max(max_accel, restart.at(t).acceleration.norm());
    max_step = std::max(max_step, (restart.at(t + 0.01).velocity - restart.at(t).velocity).norm());
  }
  EXPECT_LT(max_accel, 2.0 * config.path_limits.longitudinal.accel);
  EXPECT_LT(max_step, 0.01 * 2.0 * config.path_limits.longitudinal.accel);
  // After the ramp it is the base, shifted in time.
  EXPECT_LT((restart.at(ramp + 0.4).velocity - base->at(t0 + ramp / 2 + 0.4).velocity).norm(),
            1e-9);
}

TEST(RestartFromRest, theNearestTimeIsFoundWithinTheWindow) {
  const wd::ChairParams p = wd::test::shippedChair();
  const wc::PreparedPath prepared = wc::preparePath(
      wc::PathBuilder({0.0, 0.0, 0.0}).straight(4.0).poses(), p, wc::TrackerConfig{}, 0.0);
  ASSERT_TRUE(prepared.rejection.empty());
  const wc::OutputTrajectory& base = *prepared.trajectories.front();
  const Eigen::Vector2d y = base.at(3.217).position + Eigen::Vector2d(0.0, 0.05);
  EXPECT_NEAR(wc::nearestTime(base, y, 0.0, base.duration()), 3.217, 2e-3);
  EXPECT_NEAR(wc::nearestTime(base, y, 0.0, 2.0), 2.0, 1e-9) << "clamped to the window";
}
