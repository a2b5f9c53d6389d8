// The driver core on a fake bus against an emulated motor controller, with injected time.
#include "harness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace wheelchair_base_driver {
namespace {

namespace protocol = wheelchair_can::protocol;
using protocol::TorqueCommand;
using test::CanFrame;
using test::FakeBusEndpoint;
using test::Harness;

/// Every torque command and heartbeat seen on the bus (the monitor endpoint).
struct BusLog {
  std::vector<std::pair<double, TorqueCommand>> commands;
  std::vector<double> controller_heartbeats, driver_heartbeats;
  void drain(FakeBusEndpoint& monitor) {
    std::vector<CanFrame> rx;
    monitor.receive(rx);
    for (const CanFrame& f : rx) {
      protocol::Message m;
      if (protocol::decode(f, &m) != protocol::DecodeError::kNone) continue;
      if (auto* c = std::get_if<TorqueCommand>(&m)) commands.emplace_back(f.stamp, *c);
      if (std::holds_alternative<protocol::ControllerHeartbeat>(m))
        controller_heartbeats.push_back(f.stamp);
      if (std::holds_alternative<protocol::DriverHeartbeat>(m))
        driver_heartbeats.push_back(f.stamp);
    }
  }
};

struct DriverTest : ::testing::Test {
  void SetUp() override {
    h.run(0.1);  // heartbeats flow, the controller's start-up fault is acknowledged
    ASSERT_EQ(h.driver.state(), DriverState::kWaitingForCommand);
    log.drain(*h.monitor);
    log = BusLog();
  }
  /// Runs with a torque message every 20 ms (a 50 Hz controller).
  void driveFor(double duration, double left, double right) {
    double next = h.now;
    h.run(duration, 0.001, [&] {
      if (h.now >= next - 1e-9) {
        h.torque(left, right);
        next += 0.02;
      }
    });
  }
  Harness h;
  BusLog log;
};

TEST_F(DriverTest, StartsBrakedAndWaitsForController) {
  Harness fresh;
  fresh.driver.spinOnce(0.0);
  EXPECT_EQ(fresh.driver.state(), DriverState::kNoController);
  EXPECT_TRUE(fresh.driver.lastCommand().brake);
  fresh.now = 0.001;
  fresh.permit();
  fresh.torque(5, 5);
  EXPECT_TRUE(fresh.driver.lastCommand().brake);  // no controller: no torque
}

TEST_F(DriverTest, TorquesReachTheMotorsWithScaleAndSign) {
  h.torque(12.34, -7.89);
  EXPECT_EQ(h.driver.state(), DriverState::kDriving);
  EXPECT_TRUE(h.driver.lastCommand().enable);
  h.run(0.002);
  EXPECT_NEAR(h.plant.leftTorque(), 12.34, 0.005);
  EXPECT_NEAR(h.plant.rightTorque(), -7.89, 0.005);
  EXPECT_FALSE(h.plant.braked());
  driveFor(0.5, 10.0, 10.0);
  EXPECT_GT(h.plant.leftRate(), 0.0);  // positive torque rolls the wheel forward
  EXPECT_GT(h.driver.odometry().v, 0.0);
  EXPECT_GT(h.driver.odometry().pose.x, 0.0);
  // The first 2 ms of (12.34, -7.89) spun the left wheel up more: the chair turned right.
  EXPECT_LT(h.driver.odometry().pose.yaw, 0.0);
}

TEST_F(DriverTest, CommandSilenceBrakesAtTheTimeout) {
  const double t0 = h.now;
  h.torque(5.0, 5.0);
  double brake_time = -1;
  h.run(0.3, 0.0001, [&] {
    if (brake_time < 0 && h.driver.state() == DriverState::kCommandTimeout) brake_time = h.now;
  });
  log.drain(*h.monitor);
  double first_brake_frame = -1;
  for (const auto& [stamp, c] : log.commands) {
    if (c.brake && first_brake_frame < 0) first_brake_frame = stamp;
    if (first_brake_frame < 0) {
      EXPECT_NEAR(c.left, 5.0, 1e-9);
    }
  }
  ASSERT_GT(first_brake_frame, 0);
  EXPECT_GE(first_brake_frame - t0, 0.1 - 1e-9);
  EXPECT_LE(first_brake_frame - t0, 0.1 + 0.0001 + 1e-9);
  EXPECT_EQ(h.driver.counters().command_timeouts, 1u);
  EXPECT_TRUE(h.plant.braked());
  EXPECT_EQ(h.plant.leftTorque(), 0.0);
}

TEST_F(DriverTest, CommandsAt50HzNeverBrake) {
  driveFor(1.0, 3.0, 3.0);
  log.drain(*h.monitor);
  ASSERT_GT(log.commands.size(), 90u);
  for (const auto& [stamp, c] : log.commands) {
    EXPECT_TRUE(c.enable && !c.brake) << "at " << stamp;
  }
  EXPECT_EQ(h.driver.counters().command_timeouts, 0u);
}

TEST_F(DriverTest, FramesAreSentAtTheFixedRate) {
  h.run(1.0);
  log.drain(*h.monitor);
  EXPECT_NEAR(static_cast<double>(log.commands.size()), 100.0, 1.0);
  EXPECT_NEAR(static_cast<double>(log.driver_heartbeats.size()), 20.0, 1.0);
  EXPECT_NEAR(static_cast<double>(log.controller_heartbeats.size()), 20.0, 1.0);
}

TEST_F(DriverTest, HeartbeatLossFaultsAndBrakes) {
  driveFor(0.1, 4.0, 4.0);
  h.controller.setSilent(true);
  const double silent_from = h.now;
  double lost_at = -1;
  double next = h.now;
  h.run(0.4, 0.0001, [&] {
    if (h.now >= next - 1e-9) {
      h.torque(4.0, 4.0);
      next += 0.02;
    }
    if (lost_at < 0 && isFault(h.driver.state())) lost_at = h.now;
  });
  log.drain(*h.monitor);
  double last_heartbeat = -1;
  for (double t : log.controller_heartbeats) {
    if (t <= silent_from) last_heartbeat = t;
  }
  ASSERT_GT(lost_at, 0);
  EXPECT_GE(lost_at - last_heartbeat, 0.2 - 1e-9);
  EXPECT_LE(lost_at - last_heartbeat, 0.2 + 0.0002);
  EXPECT_EQ(h.driver.state(), DriverState::kLatched) << "lost while driving: the drive ends";
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kInterrupted);
  EXPECT_EQ(h.driver.sentence(), "the motor controller stopped answering");
  EXPECT_TRUE(isFault(h.driver.state()));
  EXPECT_TRUE(h.driver.lastCommand().brake);
  EXPECT_TRUE(h.plant.braked());  // the controller still hears the brake command
  EXPECT_EQ(h.driver.counters().heartbeat_losses, 1u);
  // Heartbeats return: commands alone do not move the chair again, only the rider's release
  // and then a command newer than it.
  h.controller.setSilent(false);
  h.run(0.06);
  driveFor(0.1, 4.0, 4.0);
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
  EXPECT_TRUE(h.plant.braked());
  h.driver.riderRelease(h.now);
  EXPECT_EQ(h.driver.state(), DriverState::kWaitingForCommand);
  h.run(0.001);
  h.torque(4.0, 4.0);
  EXPECT_EQ(h.driver.state(), DriverState::kDriving);
}

TEST_F(DriverTest, EstopLatchesUntilClearedAndNeedsAFreshCommand) {
  driveFor(0.1, 6.0, 6.0);
  h.driver.engageEstop(h.now);
  EXPECT_EQ(h.driver.state(), DriverState::kEstop);
  EXPECT_TRUE(h.driver.lastCommand().brake);
  log.drain(*h.monitor);
  log = BusLog();
  driveFor(0.5, 6.0, 6.0);  // commands keep coming: the stop holds
  log.drain(*h.monitor);
  for (const auto& [stamp, c] : log.commands) EXPECT_TRUE(c.brake) << stamp;
  EXPECT_TRUE(h.plant.braked());
  EXPECT_TRUE(h.driver.estopLatched());
  h.driver.riderRelease(h.now);  // only the rider's release (the e-stop clear service refuses)
  EXPECT_EQ(h.driver.state(), DriverState::kWaitingForCommand);  // the last message is old
  h.run(0.005);
  EXPECT_TRUE(h.plant.braked());
  h.torque(6.0, 6.0);
  EXPECT_EQ(h.driver.state(), DriverState::kDriving);
  EXPECT_EQ(h.driver.counters().estops, 1u);
}

TEST_F(DriverTest, InvalidTorquesAreRejectedCountedAndBrake) {
  const double inf = std::numeric_limits<double>::infinity();
  const struct {
    double left, right, stamp_age;
    TorqueVerdict verdict;
  } kCases[] = {{std::nan(""), 1, 0, TorqueVerdict::kNonFinite},
                {1, inf, 0, TorqueVerdict::kNonFinite},
                {-inf, 1, 0, TorqueVerdict::kNonFinite},
                {40.01, 0, 0, TorqueVerdict::kOutOfRange},
                {0, -41, 0, TorqueVerdict::kOutOfRange},
                {1, 1, 0.1, TorqueVerdict::kStale},
                {1, 1, -0.02, TorqueVerdict::kFuture}};
  for (const auto& c : kCases) {
    h.torque(2.0, 2.0);
    ASSERT_EQ(h.driver.state(), DriverState::kDriving);
    EXPECT_EQ(h.torque(c.left, c.right, false, c.stamp_age), c.verdict);
    EXPECT_EQ(h.driver.state(), DriverState::kWaitingForCommand);
    EXPECT_TRUE(h.driver.lastCommand().brake);
    EXPECT_EQ(h.driver.lastCommand().left, 0.0);
    h.run(0.002);
    EXPECT_TRUE(h.plant.braked());
  }
  const DriverCounters& n = h.driver.counters();
  EXPECT_EQ(n.rejected_non_finite, 3u);
  EXPECT_EQ(n.rejected_out_of_range, 2u);
  EXPECT_EQ(n.rejected_stale, 2u);
  EXPECT_EQ(h.torque(40.0, -40.0, false, 0.05), TorqueVerdict::kAccepted);  // limits are valid
}

// Commands carry their creation time and sequence: a command older than the watchdog, one
// without a stamp or one replayed (a sequence not above the last) never drives; a new session
// (the controller reloaded) starts its own sequence.
TEST_F(DriverTest, StaleUnstampedAndReplayedCommandsAreRejected) {
  h.torque(2.0, 2.0);
  ASSERT_EQ(h.driver.state(), DriverState::kDriving);
  const std::uint64_t last = h.command_sequence;
  EXPECT_EQ(h.driver.onCommand({2, 2, false, h.now, last, 1}, h.now), TorqueVerdict::kReplayed);
  EXPECT_EQ(h.driver.state(), DriverState::kWaitingForCommand);
  EXPECT_EQ(h.driver.onCommand({2, 2, false, 0.0, last + 1, 1}, h.now), TorqueVerdict::kUnstamped);
  EXPECT_EQ(h.driver.onCommand({2, 2, false, h.now - 0.1, last + 2, 1}, h.now),
            TorqueVerdict::kStale);
  h.run(0.001);
  EXPECT_EQ(h.driver.onCommand({2, 2, false, h.now, 1, 2}, h.now), TorqueVerdict::kAccepted)
      << "a reloaded controller is a new session";
  EXPECT_EQ(h.driver.state(), DriverState::kDriving);
}

TEST_F(DriverTest, BrakeRequestInTheMessageBrakes) {
  h.torque(3.0, 3.0, true);
  EXPECT_EQ(h.driver.state(), DriverState::kBraking);
  EXPECT_TRUE(h.driver.lastCommand().brake);
  EXPECT_EQ(h.driver.lastCommand().left, 0.0);
  EXPECT_FALSE(isFault(h.driver.state()));
}

// Every braking fault bit brakes at once, and during a drive it latches (released by the rider);
// the bad-frame report ends the drive with the controller's controlled stop instead.
TEST_F(DriverTest, EveryControllerFaultBitBrakes) {
  for (int bit = 0; bit < protocol::kFaultBitCount; ++bit) {
    const auto fault = static_cast<std::uint16_t>(1u << bit);
    driveFor(0.04, 2.0, 2.0);
    ASSERT_EQ(h.driver.state(), DriverState::kDriving) << bit;
    h.controller.setInjectedFaults(fault);
    driveFor(0.02, 2.0, 2.0);  // at least one status frame (10 ms)
    EXPECT_EQ(h.driver.controllerFaults(), fault);
    if (fault & protocol::kReportOnlyFaults) {
      EXPECT_EQ(h.driver.state(), DriverState::kStopping) << bit;
      EXPECT_EQ(h.driver.latchCause(), LatchCause::kCorruptStream);
      EXPECT_FALSE(h.plant.braked()) << "the controlled stop runs on valid frames";
    } else {
      EXPECT_EQ(h.driver.state(), DriverState::kLatched) << bit;
      EXPECT_EQ(h.driver.latchCause(), LatchCause::kInterrupted) << bit;
      EXPECT_TRUE(h.driver.lastCommand().brake);
      EXPECT_TRUE(h.plant.braked());
    }
    h.controller.setInjectedFaults(0);
    h.driver.riderRelease(h.now);
    h.run(0.02);
  }
}

TEST_F(DriverTest, OdometryMatchesTheWheelsMotion) {
  driveFor(2.0, 2.0, 3.0);
  const OdometryState& odo = h.driver.odometry();
  const double count = 2 * M_PI / 4096;
  // The last encoder frame is at most one encoder period (10 ms) old.
  EXPECT_NEAR(odo.left_angle, h.plant.wheelAngles().left, count + 0.011 * h.plant.leftRate());
  EXPECT_NEAR(odo.right_angle, h.plant.wheelAngles().right, count + 0.011 * h.plant.rightRate());
  EXPECT_NEAR(odo.v, 0.17 * (h.plant.leftRate() + h.plant.rightRate()) / 2, 0.02);
  EXPECT_NEAR(odo.omega, 0.17 * (h.plant.rightRate() - h.plant.leftRate()) / 0.56, 0.05);
  EXPECT_GT(odo.pose.yaw, 0.0);  // right wheel faster: turning left (counter-clockwise)
  EXPECT_EQ(h.driver.counters().encoder_lost, 0u);
}

TEST_F(DriverTest, ErrorFramesAndForeignCommandsAreCounted) {
  CanFrame error;
  error.error = true;
  error.id = 0x40;  // CAN_ERR_BUSOFF
  h.bus->inject(error);
  h.monitor->send(protocol::encode(TorqueCommand{1, 1, true, false, 0}));
  h.run(0.002);
  EXPECT_EQ(h.driver.counters().error_frames, 1u);
  EXPECT_NE(h.driver.lastBusError().find("bus-off"), std::string::npos);
  EXPECT_EQ(h.driver.counters().foreign_commands, 1u);
  // Another sender of torque commands on the bus: braked and latched.
  EXPECT_EQ(h.driver.state(), DriverState::kLatched);
  EXPECT_EQ(h.driver.latchCause(), LatchCause::kForeignCommand);
  EXPECT_EQ(h.driver.sentence(), "another device is sending motor commands");
}

TEST(DriverConfig, ValidationNamesTheBadValue) {
  DriverConfig c = test::testDriverConfig();
  c.geometry.wheel_radius = std::nan("");
  EXPECT_NE(c.validate().find("wheel_radius"), std::string::npos) << c.validate();
  auto port = wheelchair_can::FakeBus::create()->connect("driver");
  EXPECT_THROW(BaseDriverCore(c, *port), std::invalid_argument);
  c = test::testDriverConfig();
  c.max_torque = 400;
  EXPECT_NE(c.validate().find("max_torque exceeds"), std::string::npos) << c.validate();
  EXPECT_THROW(BaseDriverCore(c, *port), std::invalid_argument);
  EXPECT_EQ(test::testDriverConfig().validate(), "");
}

}  // namespace
}  // namespace wheelchair_base_driver
