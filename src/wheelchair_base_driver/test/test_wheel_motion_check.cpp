// WheelMotionCheck alone, with synthetic wheels at 100 Hz: each fault within its bound, and the
// motions that are no fault (braking against the motion, both wheels turning, a wheel at rest
// with no torque while the other turns slowly).
#include <wheelchair_base_driver/wheel_motion_check.h>

#include <gtest/gtest.h>

#include <functional>

namespace wheelchair_base_driver {
namespace {

DriverConfig config() {
  DriverConfig c;
  c.max_torque = 50.0;
  return c;
}

/// Runs `duration` s of encoder frames at 100 Hz; `wheels(t)` gives (left, right) at t since the
/// start. Returns the first verdict with a fault (or none) and its time.
struct Outcome {
  WheelVerdict verdict;
  double at = -1.0;
};
Outcome run(WheelMotionCheck& check, double duration,
            const std::function<std::pair<WheelState, WheelState>(double)>& wheels) {
  check.reset(0.0, wheels(0.0).first.angle, wheels(0.0).second.angle);
  for (int i = 1; i <= static_cast<int>(duration * 100); ++i) {
    const double t = i * 0.01;
    const auto [l, r] = wheels(t);
    check.onEncoder(t, l.angle, r.angle);
    const WheelVerdict v = check.check(t, true, l, r);
    if (v.fault != WheelFault::kNone) return {v, t};
  }
  return {};
}

TEST(WheelMotionCheck, AFrozenLeftEncoderIsFoundWithinTheCheckAngleOfTheOtherWheel) {
  WheelMotionCheck check(config());
  const double rate = 4.0;  // [rad/s] 0.68 m/s
  const Outcome r = run(check, 1.0, [&](double t) {
    // The controller, seeing the left wheel stand, pushes it (36 N m in the system test).
    return std::make_pair(WheelState{30.0, 0.0, 0.0}, WheelState{5.0, rate * t, rate});
  });
  ASSERT_EQ(r.verdict.fault, WheelFault::kFrozenEncoder) << r.verdict.detail;
  EXPECT_LE(rate * r.at, config().encoder_check_angle + rate * 0.01);
  EXPECT_NE(r.verdict.detail.find("left"), std::string::npos) << r.verdict.detail;
}

TEST(WheelMotionCheck, AWheelUnderTorqueThatDoesNotTurnIsStalled) {
  WheelMotionCheck check(config());
  const double tau = config().stall_torque;
  const Outcome r = run(check, 1.0, [&](double) {
    return std::make_pair(WheelState{tau, 1.0, 0.0}, WheelState{tau, 2.0, 0.0});
  });
  ASSERT_EQ(r.verdict.fault, WheelFault::kStalled) << r.verdict.detail;
  EXPECT_NEAR(r.at, config().stall_time, 0.011);
}

TEST(WheelMotionCheck, AWheelSpeedingUpAgainstItsTorqueIsFound) {
  // An encoder wired backwards: the wheel goes forward under forward torque but reads backwards,
  // faster and faster (the controller pushes harder).
  WheelMotionCheck check(config());
  const double tau = 30.0;
  const Outcome r = run(check, 1.0, [&](double t) {
    const double rate = -(1.5 + 3.0 * t);
    return std::make_pair(WheelState{tau, -(1.5 * t + 1.5 * t * t), rate},
                          WheelState{tau, 1.5 * t + 1.5 * t * t, -rate});
  });
  ASSERT_EQ(r.verdict.fault, WheelFault::kAgainstCommand) << r.verdict.detail;
  EXPECT_NEAR(r.at, config().stall_time, 0.021);
}

TEST(WheelMotionCheck, BrakingAgainstTheMotionIsNoFault) {
  WheelMotionCheck check(config());
  const Outcome r = run(check, 1.0, [&](double t) {  // 5 rad/s slowing at 4 rad/s^2 under -30 N m
    const double rate = 5.0 - 4.0 * t, angle = 5.0 * t - 2.0 * t * t;
    return std::make_pair(WheelState{-30.0, angle, rate}, WheelState{-30.0, angle, rate});
  });
  EXPECT_EQ(r.verdict.fault, WheelFault::kNone) << r.verdict.detail;
}

TEST(WheelMotionCheck, BothWheelsTurningUnderFullTorqueIsNoFault) {
  WheelMotionCheck check(config());
  const Outcome r = run(check, 2.0, [&](double t) {
    return std::make_pair(WheelState{50.0, 2.0 * t * t, 4.0 * t},
                          WheelState{50.0, 2.0 * t * t, 4.0 * t});
  });
  EXPECT_EQ(r.verdict.fault, WheelFault::kNone) << r.verdict.detail;
}

TEST(WheelMotionCheck, ATightTurnWithTheInnerWheelCreepingIsNoFault) {
  // The inner wheel at 0.05 rad/s (a count every 31 ms) while the outer turns at 2 rad/s.
  WheelMotionCheck check(config());
  const double count = 2.0 * M_PI / 4096.0;
  const Outcome r = run(check, 2.0, [&](double t) {
    const double inner = std::floor(0.05 * t / count) * count;
    return std::make_pair(WheelState{3.0, inner, 0.05}, WheelState{6.0, 2.0 * t, 2.0});
  });
  EXPECT_EQ(r.verdict.fault, WheelFault::kNone) << r.verdict.detail;
}

TEST(WheelMotionCheck, ASlowTurnAboutAStandingInnerWheelIsNoFault) {
  // Seen in the one-switch drive: the left wheel stood 0.39 s while the right turned 0.25 rad
  // (0.64 rad/s): the chair turning about its left wheel, not a failed encoder.
  WheelMotionCheck check(config());
  const Outcome r = run(check, 0.39, [&](double t) {
    return std::make_pair(WheelState{2.0, 0.0, 0.0}, WheelState{6.0, 0.64 * t, 0.64});
  });
  EXPECT_EQ(r.verdict.fault, WheelFault::kNone) << r.verdict.detail;
}

TEST(WheelMotionCheck, AFastTurnAboutAStandingWheelUnderALightTorqueIsNoFault) {
  // Seen in the navigation_person system test (CI): the left wheel stood 0.14 s while the right
  // turned 0.26 rad (1.9 rad/s) on the way round a person; the left motor was not pushing it.
  WheelMotionCheck check(config());
  const Outcome r = run(check, 1.0, [&](double t) {
    return std::make_pair(WheelState{4.0, 0.0, 0.0}, WheelState{6.0, 1.9 * t, 1.9});
  });
  EXPECT_EQ(r.verdict.fault, WheelFault::kNone) << r.verdict.detail;
}

TEST(WheelMotionCheck, TheFrozenEncoderReportSaysHowHardTheMotorPushed) {
  WheelMotionCheck check(config());
  const Outcome r = run(check, 1.0, [&](double t) {
    return std::make_pair(WheelState{30.0, 0.0, 0.0}, WheelState{-10.0, 4.0 * t, 4.0});
  });
  ASSERT_EQ(r.verdict.fault, WheelFault::kFrozenEncoder) << r.verdict.detail;
  EXPECT_NE(r.verdict.detail.find("its torque 30.0 N m"), std::string::npos) << r.verdict.detail;
}

}  // namespace
}  // namespace wheelchair_base_driver
