// Encoder odometry against analytic motions of a differential drive.
#include <wheelchair_base_driver/encoder_odometry.h>
#include <wheelchair_core/kinematics.h>

#include <gtest/gtest.h>

#include <cmath>

namespace wheelchair_base_driver {
namespace {

WheelGeometry geometry() {
  WheelGeometry g;
  g.wheel_radius = 0.17;
  g.half_track = 0.28;
  g.counts_per_rev = 4096;
  g.max_wheel_rate = 40;
  return g;
}

std::uint32_t counts(double angle) {
  return static_cast<std::uint32_t>(std::llround(angle / (2 * M_PI) * 4096)) & 0xFFFFFF;
}

// The odometry's kinematics are wheelchair_core's eq. 10-11 (left 2 rad/s, right 4 rad/s).
TEST(BodyTwist, MatchesTheDifferentialDriveKinematics) {
  const wheelchair_core::BodyTwist t = wheelchair_core::bodyTwist({4.0, 2.0}, geometry().base());
  EXPECT_DOUBLE_EQ(t.v, 0.17 * 3.0);
  EXPECT_DOUBLE_EQ(t.omega, 0.17 * 2.0 / 0.56);
}

TEST(EncoderOdometry, StraightLineAcrossTheCounterWrap) {
  EncoderOdometry odo(geometry());
  const std::uint32_t start = 0xFFFFFF - 2000;  // wraps during the run
  odo.update({start, start, 0}, 0.0);
  for (int i = 1; i <= 100; ++i) {
    const std::uint32_t c = (start + 41u * i) & 0xFFFFFF;
    ASSERT_TRUE(odo.update({c, c, static_cast<std::uint8_t>(i)}, 0.01 * i));
  }
  const double distance = 4100.0 / 4096 * 2 * M_PI * 0.17;
  EXPECT_NEAR(odo.state().pose.x, distance, 1e-9);
  EXPECT_NEAR(odo.state().pose.y, 0.0, 1e-12);
  EXPECT_NEAR(odo.state().pose.yaw, 0.0, 1e-12);
  EXPECT_NEAR(odo.state().v, 41.0 / 4096 * 2 * M_PI * 0.17 / 0.01, 1e-9);
  EXPECT_NEAR(odo.state().left_angle, 4100.0 / 4096 * 2 * M_PI, 1e-9);
}

TEST(EncoderOdometry, TurnInPlace) {
  EncoderOdometry odo(geometry());
  odo.update({0, 0, 0}, 0.0);
  const std::uint32_t n = 1000;
  odo.update({(0u - n) & 0xFFFFFF, n, 1}, 0.5);
  const double wheel = n / 4096.0 * 2 * M_PI;
  EXPECT_NEAR(odo.state().pose.yaw, 0.17 * 2 * wheel / 0.56, 1e-12);
  EXPECT_NEAR(odo.state().pose.x, 0.0, 1e-12);
  EXPECT_NEAR(odo.state().pose.y, 0.0, 1e-12);
  EXPECT_NEAR(odo.state().omega, 0.17 * 2 * wheel / 0.56 / 0.5, 1e-9);
}

TEST(EncoderOdometry, ConstantRatesFollowTheAnalyticCircle) {
  const WheelGeometry g = geometry();
  EncoderOdometry odo(g);
  const double rate_l = 3.0, rate_r = 5.0, dt = 0.01;
  const wheelchair_core::BodyTwist twist = wheelchair_core::bodyTwist({rate_r, rate_l}, g.base());
  odo.update({0, 0, 0}, 0.0);
  for (int i = 1; i <= 300; ++i) {
    const double t = i * dt;
    odo.update({counts(rate_l * t), counts(rate_r * t), static_cast<std::uint8_t>(i)}, t);
  }
  const double t = 3.0, radius = twist.v / twist.omega;
  // Quantisation: half a count per wheel, 2 pi / 4096 / 2 rad * r = 1.3e-4 m.
  EXPECT_NEAR(odo.state().pose.x, radius * std::sin(twist.omega * t), 5e-4);
  EXPECT_NEAR(odo.state().pose.y, radius * (1 - std::cos(twist.omega * t)), 5e-4);
  EXPECT_NEAR(odo.state().pose.yaw, twist.omega * t, 2e-3);
}

TEST(EncoderOdometry, SameStampIsFoldedIntoTheNextSample) {
  EncoderOdometry odo(geometry());
  odo.update({0, 0, 0}, 1.0);
  odo.update({100, 100, 1}, 1.0);  // no elapsed time
  odo.update({200, 200, 2}, 1.1);
  EXPECT_NEAR(odo.state().left_angle, 200.0 / 4096 * 2 * M_PI, 1e-12);
}

TEST(EncoderOdometry, ImplausibleJumpIsRejectedAndResyncs) {
  EncoderOdometry odo(geometry());
  odo.update({0, 0, 0}, 0.0);
  // 40 rad/s for 10 ms is 26 counts; 5000 counts is a corrupted value.
  EXPECT_FALSE(odo.update({5000, 0, 1}, 0.01));
  EXPECT_DOUBLE_EQ(odo.state().pose.x, 0.0);
  EXPECT_TRUE(odo.update({5010, 10, 2}, 0.02));  // new reference
  EXPECT_TRUE(odo.update({5020, 20, 3}, 0.03));
  EXPECT_NEAR(odo.state().left_angle, 10.0 / 4096 * 2 * M_PI, 1e-12);
}

}  // namespace
}  // namespace wheelchair_base_driver
