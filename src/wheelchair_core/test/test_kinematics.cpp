#include <gtest/gtest.h>
#include <wheelchair_core/kinematics.h>

#include <cmath>

namespace wheelchair_core {
namespace {

const WheelBase kBase{0.17, 0.28};

TEST(Kinematics, EqualWheelRatesDriveStraight) {
  const BodyTwist t = bodyTwist({2.0, 2.0}, kBase);
  EXPECT_NEAR(t.v, 0.34, 1e-12);
  EXPECT_NEAR(t.omega, 0.0, 1e-12);
}

TEST(Kinematics, OppositeWheelRatesTurnOnTheSpot) {
  // Each wheel rolls r*psi_dot along a circle of radius b: omega = r psi_dot / b.
  const BodyTwist t = bodyTwist({1.0, -1.0}, kBase);
  EXPECT_NEAR(t.v, 0.0, 1e-12);
  EXPECT_NEAR(t.omega, 0.17 / 0.28, 1e-12);
}

TEST(Kinematics, WheelRatesInvertTheBodyTwist) {
  const WheelRates w = wheelRates({0.7, -0.4}, kBase);
  const BodyTwist t = bodyTwist(w, kBase);
  EXPECT_NEAR(t.v, 0.7, 1e-12);
  EXPECT_NEAR(t.omega, -0.4, 1e-12);
}

TEST(Kinematics, ArcIntegrationLandsOnTheCircle) {
  // A quarter circle of radius 2 from the origin facing +x ends at (2, 2) facing +y,
  // in one step or in many.
  const double radius = 2.0, turn = M_PI / 2;
  const Pose2D one = integrateArc({}, {radius * turn, turn});
  EXPECT_NEAR(one.x, 2.0, 1e-12);
  EXPECT_NEAR(one.y, 2.0, 1e-12);
  EXPECT_NEAR(one.yaw, M_PI / 2, 1e-12);
  Pose2D many;
  for (int i = 0; i < 100; ++i) many = integrateArc(many, {radius * turn / 100, turn / 100});
  EXPECT_NEAR(many.x, 2.0, 1e-12);
  EXPECT_NEAR(many.y, 2.0, 1e-12);
}

TEST(Kinematics, WheelTravelGivesArcLengthAndTurn) {
  const BodyMotion m = bodyMotion(0.3, 0.1, 0.25);
  EXPECT_NEAR(m.distance, 0.2, 1e-12);
  EXPECT_NEAR(m.turn, 0.4, 1e-12);
}

}  // namespace
}  // namespace wheelchair_core
