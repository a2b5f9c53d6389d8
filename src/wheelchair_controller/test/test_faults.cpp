// Every fault ends in a controlled stop: decelerate within the comfort limits, then zero torque
// and the brake. The chair is driven on the model until it cruises, then the fault is injected.
#include <wheelchair_controller/path_tracker.h>
#include <wheelchair_controller_test/axle_pose.h>
#include <wheelchair_controller_test/test_paths.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <functional>

namespace wc = wheelchair_controller;
namespace wd = wheelchair_description;

namespace {

struct FaultRun {
  wc::TrackerOutput last;
  double speed_at_fault = 0.0;
  double max_decel = 0.0;       ///< of the axle centre after the fault [m/s^2]
  double time_to_brake = -1.0;  ///< after the fault [s]
  bool torque_after_brake = false;
};

/// Drives a 6 m straight at 50 Hz; at t_fault, `inject` may change the pose given to the
/// tracker (return nullopt for none) or call tracker methods.
FaultRun run(const std::function<std::optional<wc::PoseMeasurement>(
                 wc::PathTracker&, double t, const wc::PoseMeasurement& truth)>& inject) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, wc::TrackerConfig{});
  tracker.setPath(wc::PathBuilder({0.0, 0.0, 0.0}).straight(6.0).poses());
  wd::State x = wd::stateAtAxlePose(0.0, 0.0, 0.0, p);
  FaultRun r;
  const double t_fault = 4.0, dt = 0.02;
  double prev_v = 0.0;
  for (int k = 0; k < 1000; ++k) {
    const double t = k * dt;
    const wc::PoseMeasurement truth{t, wc::axlePose2D(x, p)};
    std::optional<wc::PoseMeasurement> pose = truth;
    if (t >= t_fault) pose = inject(tracker, t, truth);
    r.last = tracker.update(t, pose, {t, x.tail<2>()});
    const double v = wd::bodyVelocity(x.tail<2>(), p)(0);
    if (std::abs(t - t_fault) < 1e-9) r.speed_at_fault = v;
    if (t > t_fault) r.max_decel = std::max(r.max_decel, std::abs(v - prev_v) / dt);
    prev_v = v;
    if (r.last.command.brake && t >= t_fault) {
      if (r.time_to_brake < 0.0) r.time_to_brake = t - t_fault;
      x.tail<2>().setZero();
    } else if (r.time_to_brake >= 0.0) {
      r.torque_after_brake = true;
    }
    if (r.time_to_brake >= 0.0 && t > t_fault + r.time_to_brake + 0.5) break;
    if (!r.last.command.brake) {
      for (int i = 0; i < 20; ++i) x = wd::integrateRK4(x, r.last.command.torque, 1e-3, p);
    }
  }
  return r;
}

void expectControlledStop(const FaultRun& r, const std::string& reason_part) {
  EXPECT_GT(r.speed_at_fault, 0.5) << "the fault must hit a moving chair";
  EXPECT_EQ(r.last.state, wc::TrackerState::kAborted);
  EXPECT_NE(r.last.reason.find(reason_part), std::string::npos) << r.last.reason;
  EXPECT_TRUE(r.last.command.brake);
  EXPECT_EQ(r.last.command.torque, Eigen::Vector2d::Zero());
  EXPECT_FALSE(r.torque_after_brake);
  EXPECT_LE(r.max_decel, 0.5 * 1.05) << "decelerates within the comfort limit";
  // From 0.8 m/s at 0.5 m/s^2 with jerk 1: ramp ~2.1 s, + detection (stale: 0.2 s) + the
  // wheel-speed loop's tail to the 3 mm/s rest speed; never a jump (braking at speed).
  EXPECT_GT(r.time_to_brake, r.speed_at_fault / 0.5);
  EXPECT_LT(r.time_to_brake, r.speed_at_fault / 0.5 + 3.5);
}

}  // namespace

TEST(Faults, NaNInPathStops) {
  expectControlledStop(
      run([](wc::PathTracker& tr, double t, const wc::PoseMeasurement& truth) {
        if (std::abs(t - 4.0) < 1e-9) {
          EXPECT_EQ(tr.setPath({{0, 0, 0}, {NAN, 1, 0}, {2, 0, 0}}), "non-finite pose in path");
        }
        return std::optional<wc::PoseMeasurement>(truth);
      }),
      "non-finite");
}

TEST(Faults, ZeroLengthPathStops) {
  expectControlledStop(run([](wc::PathTracker& tr, double t, const wc::PoseMeasurement& truth) {
                         if (std::abs(t - 4.0) < 1e-9) tr.setPath({{3, 0, 0}, {3, 0, 0}});
                         return std::optional<wc::PoseMeasurement>(truth);
                       }),
                       "zero-length path");
}

TEST(Faults, EmptyPathStops) {
  expectControlledStop(run([](wc::PathTracker& tr, double t, const wc::PoseMeasurement& truth) {
                         if (std::abs(t - 4.0) < 1e-9) tr.setPath({});
                         return std::optional<wc::PoseMeasurement>(truth);
                       }),
                       "empty path");
}

TEST(Faults, PoseJumpOfOneMetreStops) {
  expectControlledStop(run([](wc::PathTracker&, double, wc::PoseMeasurement truth) {
                         truth.pose.y += 1.0;
                         return std::optional<wc::PoseMeasurement>(truth);
                       }),
                       "pose jump");
}

TEST(Faults, StalePoseStops) {
  // The pose stops arriving: the last one (t = 4 s) is repeated with its old stamp.
  std::optional<wc::PoseMeasurement> frozen;
  expectControlledStop(run([&](wc::PathTracker&, double, const wc::PoseMeasurement& truth) {
                         if (!frozen) frozen = truth;
                         return frozen;
                       }),
                       "stale pose");
}

TEST(Faults, LostLocalizationStops) {
  expectControlledStop(run([](wc::PathTracker&, double, const wc::PoseMeasurement&) {
                         return std::optional<wc::PoseMeasurement>();
                       }),
                       "localization lost");
}

TEST(Faults, NonFinitePoseStops) {
  expectControlledStop(run([](wc::PathTracker&, double, wc::PoseMeasurement truth) {
                         truth.pose.yaw = NAN;
                         return std::optional<wc::PoseMeasurement>(truth);
                       }),
                       "non-finite pose");
}

TEST(Faults, IdleTrackerHoldsTheBrake) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, wc::TrackerConfig{});
  const wc::TrackerOutput out =
      tracker.update(0.0, wc::PoseMeasurement{0.0, {0, 0, 0}}, {0.0, {0.0, 0.0}});
  EXPECT_TRUE(out.command.brake);
  EXPECT_EQ(out.command.torque, Eigen::Vector2d::Zero());
  EXPECT_EQ(out.state, wc::TrackerState::kIdle);
}

TEST(Faults, SafetyHoldStopsAndRefusesPathsUntilReleased) {
  bool refused = false;
  expectControlledStop(
      run([&](wc::PathTracker& tr, double t, const wc::PoseMeasurement& truth) {
        if (std::abs(t - 4.0) < 1e-9) tr.hold("safety", "safety stop (supervisor)");
        if (std::abs(t - 4.5) < 1e-9) {
          refused = !tr.setPath(wc::PathBuilder(truth.pose).straight(2.0).poses()).empty();
        }
        return std::optional<wc::PoseMeasurement>(truth);
      }),
      "safety stop");
  EXPECT_TRUE(refused) << "a path during the hold must be refused";
}

TEST(Faults, UserStopStops) {
  expectControlledStop(run([](wc::PathTracker& tr, double t, const wc::PoseMeasurement& truth) {
                         if (std::abs(t - 4.0) < 1e-9) tr.abort("user stop");
                         return std::optional<wc::PoseMeasurement>(truth);
                       }),
                       "user stop");
}

TEST(Faults, ReleasedHoldResumesOnlyWithANewPath) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, wc::TrackerConfig{});
  const std::vector<wc::Pose2D> path = wc::PathBuilder({0.0, 0.0, 0.0}).straight(2.0).poses();
  const wc::PoseMeasurement pose{0.0, {0, 0, 0}};
  tracker.hold("localization", "localization lost: test");
  EXPECT_FALSE(tracker.setPath(path).empty());
  double t = 0.0;
  for (; t < 1.0; t += 0.02) tracker.update(t, wc::PoseMeasurement{t, pose.pose}, {t, {0, 0}});
  EXPECT_EQ(tracker.state(), wc::TrackerState::kAborted);
  tracker.release("localization");
  const wc::TrackerOutput still = tracker.update(t, wc::PoseMeasurement{t, pose.pose}, {t, {0, 0}});
  EXPECT_TRUE(still.command.brake) << "releasing alone does not resume";
  EXPECT_TRUE(tracker.setPath(path).empty());
  const wc::TrackerOutput resumed =
      tracker.update(t + 0.02, wc::PoseMeasurement{t + 0.02, pose.pose}, {t + 0.02, {0, 0}});
  EXPECT_EQ(resumed.state, wc::TrackerState::kTracking);
  EXPECT_FALSE(resumed.command.brake);
}

// A goal given while localization is lost (e.g. before the first scan after a carer's
// re-initialization) must not vanish silently: the status the rider sees says it was ignored.
TEST(Faults, PathDuringAHoldIsRefusedOnTheStatus) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, wc::TrackerConfig{});
  tracker.hold("localization", "localization lost: waiting for the first scan");
  double t = 0.0;
  for (; t < 1.0; t += 0.02) tracker.update(t, wc::PoseMeasurement{t, {0, 0, 0}}, {t, {0, 0}});
  ASSERT_EQ(tracker.state(), wc::TrackerState::kAborted);
  const std::string refused =
      tracker.setPath(wc::PathBuilder({0.0, 0.0, 0.0}).straight(2.0).poses());
  EXPECT_NE(refused.find("path ignored during localization lost"), std::string::npos) << refused;
  wc::TrackerOutput out;
  for (; t < 2.0; t += 0.02)
    out = tracker.update(t, wc::PoseMeasurement{t, {0, 0, 0}}, {t, {0, 0}});
  EXPECT_EQ(out.state, wc::TrackerState::kAborted);
  EXPECT_EQ(out.reason, refused);
  EXPECT_TRUE(out.command.brake);
  EXPECT_EQ(out.command.torque, Eigen::Vector2d::Zero());
}

TEST(Faults, PathPreparedElsewhereIsSwappedInByTheNextStep) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, wc::TrackerConfig{});
  const wc::PreparedPath prepared = wc::preparePath(
      wc::PathBuilder({0.0, 0.0, 0.0}).straight(2.0).poses(), p, tracker.config(), 0.0);
  ASSERT_TRUE(prepared.rejection.empty()) << prepared.rejection;
  EXPECT_TRUE(tracker.setPreparedPath(prepared).empty());
  const wc::TrackerOutput out =
      tracker.update(0.0, wc::PoseMeasurement{0.0, {0, 0, 0}}, {0.0, {0.0, 0.0}});
  EXPECT_EQ(out.state, wc::TrackerState::kTracking);
  EXPECT_NEAR(out.reference.position.x(), p.lookahead, 1e-3) << "P_l reference starts at P + L";
}

// Reaching the goal ends the path; it is no stop: a path that came in the final moments (the
// rider's next goal, its reference still being built) must not be dropped as after a stop.
TEST(Faults, ReachingTheGoalIsNoStopThatDropsTheNextPath) {
  const wd::ChairParams p = wd::test::shippedChair();
  wc::PathTracker tracker(p, wc::TrackerConfig{});
  tracker.setPath(wc::PathBuilder({0.0, 0.0, 0.0}).straight(1.0).poses());
  const uint64_t stops = tracker.stopCount();
  wd::State x = wd::stateAtAxlePose(0.0, 0.0, 0.0, p);
  wc::TrackerOutput out;
  for (int k = 0; k < 1500 && out.state != wc::TrackerState::kGoalReached; ++k) {
    const double t = k * 0.02;
    out = tracker.update(t, wc::PoseMeasurement{t, wc::axlePose2D(x, p)}, {t, x.tail<2>()});
    if (out.command.brake) x.tail<2>().setZero();
    for (int i = 0; i < 20 && !out.command.brake; ++i)
      x = wd::integrateRK4(x, out.command.torque, 1e-3, p);
  }
  ASSERT_EQ(out.state, wc::TrackerState::kGoalReached) << out.reason;
  EXPECT_EQ(tracker.stopCount(), stops) << "a path prepared meanwhile would be dropped";
  tracker.abort("user stop");
  EXPECT_EQ(tracker.stopCount(), stops + 1) << "a stop still counts";
}
