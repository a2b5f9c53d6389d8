// Issue 20's command path at the driver core, on a fake bus against the emulated motor
// controller with injected time: only the chair's own controller with a fresh permit of a live
// supervisor moves the wheels; a foreign command, a vanished supervisor, a hang, a corrupted
// stream, an overspeed, a frozen encoder or a silent motor controller end the drive in one
// latched stop with the rider's sentence, released only by the rider.
#include "harness.h"

#include <wheelchair_can_testing/random_frames.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <tuple>

namespace wheelchair_base_driver {
namespace {

namespace protocol = wheelchair_can::protocol;
using test::CanFrame;
using test::Harness;

/// The chair's controller as the driver sees it: torques every 20 ms; when the driver latches a
/// stop it runs a controlled stop (torque against the motion) and brakes at rest, like the
/// controller's ControlledStop; the plant's brake engagements are counted.
struct Drive {
  explicit Drive(Harness& harness) : h(harness) {}
  void run(double duration, double torque, const std::function<void()>& each = {}) {
    h.run(duration, 0.001, [&] {
      if (each) each();
      if (h.now >= next - 1e-9) {
        next = h.now + 0.02;
        const bool stopping = h.driver.latchCause() != LatchCause::kNone || h.stop;
        if (!stopping) {
          h.torque(torque + left_push, torque);
        } else {
          const double rate = 0.5 * (h.plant.leftRate() + h.plant.rightRate());
          const bool at_rest = std::abs(rate) < 0.05;
          const double brake_torque = std::clamp(-2.0 * rate, -3.0, 3.0);  // ~0.5 m/s^2
          h.torque(at_rest ? 0.0 : brake_torque, at_rest ? 0.0 : brake_torque, at_rest);
        }
      }
      const bool braked = h.plant.braked();
      if (braked && !was_braked) {
        ++brake_engagements;
        last_engagement = h.now;
        rate_at_engagement = rate_before;
      }
      rate_before = std::abs(h.plant.leftRate());
      if (!braked && was_braked) ++brake_releases;
      was_braked = braked;
      if (h.plant.braked() == false) max_rate = std::max(max_rate, std::abs(h.plant.leftRate()));
    });
  }
  void resetCounts() { brake_engagements = brake_releases = 0; }
  Harness& h;
  double left_push = 0.0;  ///< [N m] added to the left wheel's torque (a controller correcting)
  double next = 0.0;
  bool was_braked = true;
  int brake_engagements = 0, brake_releases = 0;
  double last_engagement = -1.0, max_rate = 0.0;
  double rate_before = 0.0, rate_at_engagement = -1.0;  ///< [rad/s] when the brake engaged
};

struct CommandPathTest : ::testing::Test {
  void SetUp() override {
    h.run(0.1);
    ASSERT_EQ(h.driver.state(), DriverState::kWaitingForCommand);
  }
  Harness h;
  Drive drive{h};
};

// The issue: a second node publishing 20 N m at 500 Hz to the idle chair pushed it to 1.84 m/s.
// The driver takes torques only from its controller; a foreign publisher is braked on, latched.
TEST_F(CommandPathTest, AForeignTorquePublisherLatchesABrakedStopUntilTheRidersRelease) {
  h.driver.onForeignCommand("/intruder", h.now);
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
  EXPECT_EQ(h.driver.sentence(), "another program tried to drive the chair");
  drive.run(1.0, 20.0);  // the chair's own controller keeps commanding: the latch holds
  EXPECT_TRUE(h.plant.braked());
  EXPECT_LT(h.plant.wheelAngles().left, 1e-9);
  EXPECT_EQ(h.driver.counters().foreign_publishers, 1u);
  h.driver.riderRelease(h.now);
  drive.run(0.2, 2.0);
  EXPECT_FALSE(h.plant.braked());
  EXPECT_EQ(h.driver.state(), DriverState::kDriving);
}

TEST_F(CommandPathTest, NoPermitNoMotion) {
  Harness fresh;
  fresh.supervised = false;
  fresh.run(0.1);
  EXPECT_EQ(fresh.driver.state(), DriverState::kNoPermit);
  EXPECT_EQ(fresh.driver.sentence(), "the safety supervisor is not running");
  Drive unsupervised(fresh);
  unsupervised.run(0.5, 2.0);
  EXPECT_TRUE(fresh.plant.braked());
  fresh.supervised = true;  // the supervisor comes up: permits, and the next command drives
  unsupervised.run(0.1, 2.0);
  EXPECT_EQ(fresh.driver.state(), DriverState::kDriving);
  EXPECT_FALSE(fresh.plant.braked());
}

// The issue: the supervisor could be unloaded mid-drive and the chair drove on into a person.
TEST_F(CommandPathTest, ASupervisorThatStopsGrantingBrakesTheChairWithinThePermitTimeout) {
  drive.run(0.5, 2.0);
  ASSERT_EQ(h.driver.state(), DriverState::kDriving);
  const double last_permit = h.last_permit_time;
  h.supervised = false;  // unloaded, crashed or hanging: no more permits
  double braked_at = -1;
  drive.run(0.5, 2.0, [&] {
    if (braked_at < 0 && h.driver.lastCommand().brake) braked_at = h.now;
  });
  ASSERT_GT(braked_at, 0);
  EXPECT_GE(braked_at - last_permit, 0.1 - 1e-9);
  EXPECT_LE(braked_at - last_permit, 0.1 + 0.002) << "permit timeout 100 ms after the last one";
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
  EXPECT_EQ(h.driver.sentence(), "the safety supervisor is not running");
  EXPECT_EQ(h.driver.counters().permit_losses, 1u);
  h.supervised = true;  // a supervisor back does not restart the drive: the rider does
  drive.run(0.3, 2.0);
  EXPECT_TRUE(h.plant.braked());
  h.driver.riderRelease(h.now);
  drive.run(0.1, 2.0);
  EXPECT_EQ(h.driver.state(), DriverState::kDriving);
}

TEST_F(CommandPathTest, ReplayedOrStalePermitsAreNotPermits) {
  h.supervised = false;
  h.run(0.3);
  ASSERT_EQ(h.driver.state(), DriverState::kNoPermit);
  const std::uint64_t last = h.permit_sequence;
  for (int i = 0; i < 50; ++i) {
    h.driver.onPermit(last, 1, h.now, false, h.now);                // a replay of the last permit
    h.driver.onPermit(last + 1 + i, 1, h.now - 0.2, false, h.now);  // an old one
    h.run(0.01);
  }
  EXPECT_EQ(h.driver.state(), DriverState::kNoPermit);
  EXPECT_EQ(h.driver.counters().permits_refused, 100u);
}

// The supervisor's stop: the controller's controlled stop runs (no jolt), then the brake holds
// until the supervisor lifts the stop (the rider's release); a brake command ends the stop.
TEST_F(CommandPathTest, TheSupervisorsStopLetsTheControlledStopRunThenBrakes) {
  drive.run(1.0, 2.0);
  ASSERT_GT(h.plant.leftRate(), 2.0);
  drive.resetCounts();
  h.stop = true;
  drive.run(4.0, 2.0);
  EXPECT_EQ(drive.brake_engagements, 1);
  EXPECT_EQ(drive.brake_releases, 0);
  EXPECT_EQ(h.driver.state(), DriverState::kSupervisorStop);
  EXPECT_TRUE(h.plant.braked());
  EXPECT_LT(drive.rate_at_engagement, 0.1) << "braked at speed: a jolt";
  h.stop = false;
  drive.run(0.2, 2.0);
  EXPECT_EQ(h.driver.state(), DriverState::kDriving);
}

TEST_F(CommandPathTest, TheStopWindowBoundsAControllerThatDoesNotStop) {
  drive.run(0.5, 1.0);
  h.stop = true;
  double braked_at = -1;
  const double t0 = h.now;
  h.run(6.0, 0.001, [&] {
    if (std::fmod(h.now, 0.02) < 0.001) h.torque(1.0, 1.0);  // it keeps driving
    if (braked_at < 0 && h.plant.braked()) braked_at = h.now;
  });
  ASSERT_GT(braked_at, 0);
  EXPECT_NEAR(braked_at - t0, h.driver.config().stop_window, 0.03);
  EXPECT_EQ(h.driver.state(), DriverState::kSupervisorStop);
}

// The issue: SIGSTOP of the chair process mid-drive, then SIGCONT: the motors braked within
// 0.1 s, but the chair drove on 0.18 m without a new command. The driver now ends the drive when
// the motors braked for silence while it drove; nothing moves until the rider's release.
TEST_F(CommandPathTest, AHangMidDriveNeverResumesWithoutTheRider) {
  drive.run(1.0, 2.0);
  ASSERT_FALSE(h.plant.braked());
  // The chair process stops for 2 s: neither the controller nor the driver runs; the motor
  // controller (another device) does.
  for (int i = 0; i < 2000; ++i) {
    h.now += 0.001;
    h.controller.step(h.now);
    h.plant.advance(0.001);
  }
  EXPECT_TRUE(h.plant.braked()) << "the motor controller's watchdog braked";
  const double left_at_resume = h.plant.wheelAngles().left;
  drive.resetCounts();
  h.stop = false;
  // Resumed: the controller commands again as if nothing happened.
  h.run(1.0, 0.001, [&] {
    if (std::fmod(h.now, 0.02) < 0.001) h.torque(2.0, 2.0);
  });
  EXPECT_TRUE(h.plant.braked());
  EXPECT_NEAR(h.plant.wheelAngles().left, left_at_resume, 1e-9) << "moved after the resume";
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kInterrupted);
  EXPECT_EQ(h.driver.sentence(), "the chair's computer paused") << h.driver.latchDetail();
}

// The bus clock stands still (the simulator that owns it stopped) while the wall clock runs:
// the driver latches a stop on the wall-clock watchdog, and the brake frame waits for the MC.
TEST_F(CommandPathTest, AMotorControllerSilentInWallTimeLatchesWhileTheBusClockStandsStill) {
  drive.run(0.5, 2.0);
  ASSERT_EQ(h.driver.state(), DriverState::kDriving);
  for (double wall = h.now; wall < h.now + 1.5; wall += 0.01)
    h.driver.checkWallLiveness(h.now, wall);
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kControllerStalled);
  EXPECT_TRUE(h.driver.lastCommand().brake) << "the brake frame is on the bus for when it resumes";
  h.run(0.002);
  EXPECT_TRUE(h.plant.braked());
}

// The issue: 1 s of random frames gave 17 brake/release cycles and no latched stop. Now: one
// stop (the controller's controlled stop or the brake), latched, with the reason, no release.
TEST_F(CommandPathTest, RandomFramesOnTheBusEndInOneLatchedStop) {
  drive.run(1.0, 2.0);
  ASSERT_EQ(h.driver.state(), DriverState::kDriving);
  drive.resetCounts();
  std::mt19937_64 rng(20);
  drive.run(1.0, 2.0, [&] { h.monitor->send(wheelchair_can::test::randomFrame(rng)); });
  drive.run(4.0, 2.0);
  EXPECT_EQ(drive.brake_engagements, 1);
  EXPECT_EQ(drive.brake_releases, 0);
  EXPECT_TRUE(h.plant.braked());
  EXPECT_TRUE(isFault(h.driver.state())) << driverStateName(h.driver.state());
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kCorruptStream) << h.driver.latchDetail();
  EXPECT_EQ(h.driver.sentence(), "the motor commands were garbled");
}

// The issue, live: 5 bad frames gave one hard jolt (0.40 -> 0.28 m/s in 40 ms) and the drive
// went on. Now the drive ends in the controller's controlled stop, then the brake, latched.
TEST_F(CommandPathTest, BadCommandFramesEndTheDriveWithAControlledStop) {
  drive.run(1.0, 2.0);
  ASSERT_GT(h.plant.leftRate(), 2.0);
  drive.resetCounts();
  int bad = 0;
  drive.run(5.0, 2.0, [&] {
    if (bad < 5 && std::fmod(h.now, 0.01) < 0.001) {
      CanFrame f = protocol::encode(protocol::TorqueCommand{5, 5, true, false, 0});
      f.data[7] ^= 0x5A;  // CRC broken
      h.monitor->send(f);
      ++bad;
    }
  });
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kCorruptStream);
  EXPECT_EQ(drive.brake_engagements, 1);
  EXPECT_EQ(drive.brake_releases, 0);
  EXPECT_LT(drive.rate_at_engagement, 0.1) << "braked at speed: a jolt";
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
  EXPECT_EQ(h.driver.sentence(), "the motor commands were garbled");
}

// The driver holds the chair's speed limit itself (chair file max_speed): torque that would
// speed it up beyond the limit is cut, and the overspeed ends the drive.
TEST_F(CommandPathTest, TheDriverCutsTorqueAtMaxSpeedAndLatchesTheOverspeed) {
  double fastest = 0.0;
  h.run(3.0, 0.001, [&] {  // a controller pushing 40 N m whatever happens
    if (std::fmod(h.now, 0.02) < 0.001) h.torque(40.0, 40.0);
    fastest = std::max(fastest, 0.17 * h.plant.leftRate());
  });
  // Unlimited, 40 N m takes this light test plant to 24 m/s in 3 s; the cut comes within one
  // encoder frame (10 ms) of the plant's 13.6 m/s^2 beyond the limit.
  EXPECT_LT(fastest, 1.5 + 13.6 * 0.015) << "the driver did not hold the 1.5 m/s limit";
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kOverspeed);
  EXPECT_EQ(h.driver.sentence(), "the chair went faster than its limit");
  EXPECT_GT(h.driver.counters().speed_limited, 0u);
}

// The supervisor's speed limit (the protective field scaled to speed), carried by its permit,
// is the driver's too: the chair's controller cannot push the chair past it. The same push
// without a limit takes the chair past 1 m/s (the test can fail).
TEST_F(CommandPathTest, TheControllersTorqueCannotSpeedTheChairPastTheSupervisorsLimit) {
  const auto fastest_with_limit = [](double limit) {
    Harness chair;
    chair.speed_limit = limit;
    double fastest = 0.0;
    chair.run(3.0, 0.001, [&] {  // 2 N m whatever the speed: about 0.7 m/s^2 on this plant
      if (std::fmod(chair.now, 0.02) < 0.001) chair.torque(2.0, 2.0);
      fastest = std::max(fastest, 0.17 * chair.plant.leftRate());
    });
    EXPECT_EQ(chair.driver.state(), DriverState::kDriving) << chair.driver.latchDetail();
    EXPECT_DOUBLE_EQ(chair.driver.heldSpeedLimit(), limit);
    return std::make_pair(fastest, chair.driver.counters().speed_limited);
  };
  const auto [unlimited, unlimited_cuts] = fastest_with_limit(INFINITY);
  ASSERT_GT(unlimited, 1.0);
  EXPECT_EQ(unlimited_cuts, 0u);
  const auto [limited, cuts] = fastest_with_limit(0.5);
  // The cut comes at the limit + speed_limit_tolerance, within two encoder frames and a command
  // period (40 ms at 0.7 m/s^2).
  EXPECT_LT(limited, 0.5 + 0.05 + 0.7 * 0.04) << "the driver did not hold 0.5 m/s";
  EXPECT_GT(limited, 0.5) << "the chair should reach the limit";
  EXPECT_GT(cuts, 0u);
}

// A falling limit is held as a ramp at speed_limit_decel from the last limit: a controller that
// slows down with it drives on; one that keeps pushing (the cut leaves the chair to roll, slower
// than the ramp) ends the drive in a latched controlled stop, told.
TEST_F(CommandPathTest, AControllerThatDoesNotSlowDownWithAFallingLimitEndsTheDrive) {
  const auto fall = [](bool follow) {
    auto h = std::make_unique<Harness>();
    h->speed_limit = 1.0;
    Drive drive(*h);
    drive.run(2.0, 2.0);
    const double v0 = 0.17 * h->plant.leftRate();
    EXPECT_GT(v0, 0.8);
    EXPECT_LT(v0, 1.0 + 0.05 + 0.03);
    EXPECT_EQ(h->driver.state(), DriverState::kDriving);
    h->speed_limit = 0.2;
    const double t0 = h->now;
    double latched_at = -1.0, held_at_latch = -1.0, ramp_error = 0.0, over = 0.0;
    double next = h->now;
    h->run(3.0, 0.001, [&] {
      const double t = h->now - t0;
      const bool latched = h->driver.latchCause() != LatchCause::kNone;
      // One permit period after the fall, the ramp from the speed then (at most 1.0) at
      // 0.5 m/s^2 down to 0.2.
      if (t > 0.021 && !latched)
        ramp_error =
            std::max(ramp_error, std::abs(h->driver.heldSpeedLimit() -
                                          std::max(0.2, std::min(1.0, v0) - 0.5 * (t - 0.02))));
      if (!latched) over = std::max(over, 0.17 * h->plant.leftRate() - h->driver.heldSpeedLimit());
      if (latched_at < 0 && latched) {
        latched_at = t;
        held_at_latch = h->driver.heldSpeedLimit();
      }
      if (h->now < next - 1e-9) return;
      next = h->now + 0.02;
      const double rate = h->plant.leftRate();
      if (latched) {  // the controlled stop
        const bool at_rest = std::abs(rate) < 0.05;
        const double brake = std::clamp(-2.0 * rate, -3.0, 3.0);
        h->torque(at_rest ? 0.0 : brake, at_rest ? 0.0 : brake, at_rest);
      } else if (follow) {  // towards the limit, about 1 m/s^2 at most
        const double torque = std::clamp(4.0 * (0.2 / 0.17 - rate), -3.0, 2.0);
        h->torque(torque, torque);
      } else {
        h->torque(2.0, 2.0);
      }
    });
    EXPECT_LT(ramp_error, 0.021) << "the held limit is not the ramp";
    return std::make_tuple(std::move(h), latched_at, held_at_latch, over);
  };
  {
    auto [h, latched_at, held, over] = fall(true);
    EXPECT_LT(latched_at, 0) << h->driver.latchDetail();
    EXPECT_EQ(h->driver.state(), DriverState::kDriving);
    EXPECT_LT(over, 0.05) << "a controller slowing down with the limit was cut";
    EXPECT_NEAR(0.17 * h->plant.leftRate(), 0.2, 0.02);
    EXPECT_DOUBLE_EQ(h->driver.heldSpeedLimit(), 0.2);
  }
  {
    auto [h, latched_at, held, over] = fall(false);
    ASSERT_GT(latched_at, 0) << "a controller pushing on past the limit was not stopped";
    EXPECT_LT(latched_at, 1.0);
    EXPECT_GT(held, 0.2) << "latched before the ramp reached the limit";
    // Twice the tolerance, and the ramp's 0.5 m/s^2 for the 0.1 s over it before the latch.
    EXPECT_LT(over, 2 * 0.05 + 0.5 * 0.1) << "the chair rolled on faster than the limit allows";
    EXPECT_EQ(h->driver.latchCause(), LatchCause::kOverspeed);
    EXPECT_EQ(h->driver.sentence(), "the chair went faster than its safety limit");
    EXPECT_TRUE(h->plant.braked()) << "at rest after the controlled stop";
  }
}

// The held limit, the functions alone: a rise at once; a fall no faster than the deceleration,
// from the last held value or the chair's speed envelope if lower; the envelope follows a
// higher speed at once and a lower one (a late encoder frame) only at the deceleration.
TEST(HeldSpeedLimit, RisesAtOnceAndFallsAtTheDecelerationFromTheChairsSpeed) {
  EXPECT_DOUBLE_EQ(heldSpeedLimit(0.3, 1.2, 0.3, 1.5, 0.5, 0.02), 1.2);
  EXPECT_EQ(heldSpeedLimit(0.3, INFINITY, 0.3, 1.5, 0.5, 0.02), INFINITY);
  EXPECT_DOUBLE_EQ(heldSpeedLimit(INFINITY, 0.3, 2.0, 1.5, 0.5, 0.02), 1.5);
  EXPECT_DOUBLE_EQ(heldSpeedLimit(INFINITY, 0.3, 0.7, 1.5, 0.5, 0.02), 0.7);
  EXPECT_DOUBLE_EQ(heldSpeedLimit(INFINITY, 0.3, 0.1, 1.5, 0.5, 0.02), 0.3);
  EXPECT_DOUBLE_EQ(heldSpeedLimit(0.8, 0.3, 1.0, 1.5, 0.5, 0.02), 0.8 - 0.01);
  EXPECT_DOUBLE_EQ(heldSpeedLimit(0.31, 0.3, 1.0, 1.5, 0.5, 0.1), 0.3);
  EXPECT_DOUBLE_EQ(heldSpeedLimit(0.5, 0.0, 1.0, 1.5, 0.5, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(speedEnvelope(0.5, 0.9, 0.5, 0.01), 0.9);
  EXPECT_DOUBLE_EQ(speedEnvelope(0.5, -0.9, 0.5, 0.01), 0.9);  // reversing
  EXPECT_DOUBLE_EQ(speedEnvelope(0.9, 0.1, 0.5, 0.01), 0.9 - 0.005);
}

// ISO 7176-14 single fault: one wheel's encoder frozen while driving -> a latched stop within a
// bounded distance: the other wheel turns at most encoder_check_angle (+ one encoder frame).
TEST_F(CommandPathTest, AFrozenEncoderEndsTheDriveWithinTheCheckAngle) {
  drive.run(1.0, 2.0);
  ASSERT_EQ(h.driver.state(), DriverState::kDriving);
  const double rate = h.plant.rightRate();
  ASSERT_GT(rate, 2.0) << "the wheels should turn fast enough for the angle to matter";
  h.controller.freezeEncoders(true, false);
  // The chair's controller, seeing the left wheel stand, pushes it hard (36 N m within 0.09 s
  // in the frozen_encoder system test); a wheel standing under a light torque is a pivot.
  drive.left_push = 25.0;
  const double t0 = h.now, right0 = h.plant.wheelAngles().right;
  double latched_at = -1, right_turned = 0.0;
  drive.run(1.0, 2.0, [&] {
    if (latched_at >= 0 || h.driver.latchCause() == LatchCause::kNone) return;
    latched_at = h.now;
    right_turned = std::abs(h.plant.wheelAngles().right - right0);
  });
  ASSERT_GT(latched_at, 0);
  const auto& c = h.driver.config();
  EXPECT_LE(right_turned, c.encoder_check_angle + 0.02 * rate)
      << "latched after " << latched_at - t0;
  EXPECT_LT(latched_at - t0, c.encoder_check_time);  // the angle comes first at this speed
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kEncoderFault);
  EXPECT_EQ(h.driver.sentence(), "a wheel sensor failed");
  EXPECT_TRUE(h.plant.braked());
}

// Both encoders frozen: the odometry says the chair stands still while the controller pushes
// harder and harder. Torque of stall_torque without a count for stall_time latches a stop.
TEST_F(CommandPathTest, TorqueWithoutAnyWheelTurningEndsTheDrive) {
  drive.run(0.5, 2.0);
  ASSERT_EQ(h.driver.state(), DriverState::kDriving);
  h.controller.freezeEncoders(true, true);
  const double t0 = h.now;
  const double pushed = h.driver.config().stall_torque;
  double latched_at = -1;
  drive.run(1.5, pushed, [&] {
    if (latched_at < 0 && h.driver.latchCause() != LatchCause::kNone) latched_at = h.now;
  });
  ASSERT_GT(latched_at, 0) << "still " << driverStateName(h.driver.state());
  EXPECT_LE(latched_at - t0, h.driver.config().stall_time + 0.03);
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kWheelFault);
  EXPECT_EQ(h.driver.sentence(), "a wheel does not turn");
  EXPECT_TRUE(h.plant.braked());
}

// ISO 7176-14: power removed from the motor controller while driving: its spring brakes hold,
// the driver loses it and ends the drive; power back does not restart it.
TEST_F(CommandPathTest, PowerRemovedWhileDrivingBrakesAndLatches) {
  drive.run(1.0, 2.0);
  h.controller.setPowered(false);
  drive.run(0.5, 2.0);
  EXPECT_TRUE(h.plant.braked());
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
  EXPECT_EQ(h.driver.sentence(), "the motor controller stopped answering");
  h.controller.setPowered(true);
  drive.run(0.5, 2.0);
  EXPECT_TRUE(h.plant.braked());
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
}

// ISO 7176-14 output-device failure: the motor stage reports overcurrent while driving.
TEST_F(CommandPathTest, AnOutputStageFaultWhileDrivingBrakesAndLatches) {
  drive.run(1.0, 2.0);
  h.controller.setInjectedFaults(protocol::kFaultOvercurrentLeft);
  drive.run(0.05, 2.0);
  EXPECT_TRUE(h.plant.braked());
  EXPECT_EQ(h.driver.sentence(), "the motors report a fault");
  h.controller.setInjectedFaults(0);
  drive.run(0.5, 2.0);
  EXPECT_TRUE(h.plant.braked()) << "a fault that went away does not restart the drive";
}

// The events the stack hears: a latched stop once, with its sentence; the release once.
TEST_F(CommandPathTest, EventsSayWhenAStopLatchesAndWhenTheRiderReleasesIt) {
  while (h.driver.takeEvent()) {
  }
  drive.run(0.5, 2.0);
  EXPECT_FALSE(h.driver.takeEvent()) << "driving is no news";
  h.driver.onForeignCommand("/intruder", h.now);
  auto event = h.driver.takeEvent();
  ASSERT_TRUE(event);
  EXPECT_TRUE(event->fault);
  EXPECT_TRUE(event->latched);
  EXPECT_EQ(event->sentence, "another program tried to drive the chair");
  EXPECT_NE(event->detail.find("/intruder"), std::string::npos) << event->detail;
  drive.run(0.5, 2.0);
  EXPECT_FALSE(h.driver.takeEvent());
  h.driver.riderRelease(h.now);
  event = h.driver.takeEvent();
  ASSERT_TRUE(event);
  EXPECT_FALSE(event->latched);
  EXPECT_EQ(event->sentence, "");
}

// The supervisor forgets the driver's stop at the rider's release; the first state after a
// release is therefore reported even when the release changed nothing of it.
TEST_F(CommandPathTest, TheFirstStateAfterAReleaseIsReportedEvenWhenUnchanged) {
  drive.run(0.5, 2.0);
  while (h.driver.takeEvent()) {
  }
  h.driver.riderRelease(h.now);  // nothing was latched: no change
  auto event = h.driver.takeEvent();
  ASSERT_TRUE(event) << "the release's state was not reported";
  EXPECT_FALSE(event->latched);
  EXPECT_FALSE(event->fault);
  drive.run(0.5, 2.0);
  EXPECT_FALSE(h.driver.takeEvent()) << "only the first state after the release";
}

}  // namespace
}  // namespace wheelchair_base_driver
