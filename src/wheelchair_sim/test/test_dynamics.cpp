// The simulator's dynamics against closed forms derived independently of eq. 15 (Newton /
// energy for the rigid chair: body M_T at P_c, two wheels at P +- b).
#include <wheelchair_sim/simulator.h>
#include <wheelchair_sim/wheel_torques.h>

#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wheelchair_sim {
namespace {

namespace wd = wheelchair_description;

SimParams idealParams() {
  SimParams p;
  p.rolling_resistance = false;
  p.torque_limit = false;
  p.slip_noise = 0.0;
  return p;
}

/// Translational inertia of the chair along its heading, wheels' spin included [kg].
double forwardInertia(const wd::ChairParams& c) {
  return c.total_mass + 2.0 * c.wheel_mass + 2.0 * c.wheel_inertia / std::pow(c.wheel_radius, 2);
}

/// Inertia about the vertical through P (parallel axis theorem), wheels' spin included.
double turnInertia(const wd::ChairParams& c) {
  const double b = c.half_track, r = c.wheel_radius;
  return c.total_mass * c.cm_offset * c.cm_offset + c.body_inertia + 2.0 * c.wheel_mass * b * b +
         2.0 * c.wheel_inertia_diam + 2.0 * c.wheel_inertia * b * b / (r * r);
}

TEST(Dynamics, EqualTorquesAccelerateStraightAsNewtonSays) {
  const auto chair = test::chair();
  Simulator sim(chair, idealParams(), nullptr);
  const double yaw0 = 0.3, tau = 10.0, t = 2.0;
  ASSERT_TRUE(sim.teleport({1.0, -2.0, yaw0}));
  sim.applyWheelTorques(tau, tau, false);
  sim.step(t);
  const double a = 2.0 * tau / chair.wheel_radius / forwardInertia(chair);
  const double s = 0.5 * a * t * t;
  const wheelchair_core::Pose2D pose = sim.pose();
  EXPECT_NEAR(pose.x, 1.0 + s * std::cos(yaw0), 1e-6);
  EXPECT_NEAR(pose.y, -2.0 + s * std::sin(yaw0), 1e-6);
  EXPECT_NEAR(pose.yaw, yaw0, 1e-9);
  EXPECT_NEAR(sim.velocity().v, a * t, 1e-6);
  EXPECT_NEAR(sim.velocity().omega, 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(sim.time(), t);
}

// With the centre of mass on the axle (d = 0) opposite torques spin the chair about P at a
// constant angular acceleration.
TEST(Dynamics, OppositeTorquesTurnAboutTheAxleCentreWhenTheMassIsOnTheAxle) {
  auto chair = test::chair();
  chair.cm_offset = 0.0;
  Simulator sim(chair, idealParams(), nullptr);
  const double tau = 5.0, t = 1.5;
  ASSERT_TRUE(sim.teleport({2.0, 3.0, -0.5}));
  sim.applyWheelTorques(tau, -tau, false);
  for (int i = 0; i < 150; ++i) sim.step(0.01);
  // Power 2 tau psi_dot = 2 tau b theta_dot / r drives J theta_ddot.
  const double alpha = 2.0 * tau * chair.half_track / chair.wheel_radius / turnInertia(chair);
  EXPECT_NEAR(sim.pose().yaw, -0.5 + 0.5 * alpha * t * t, 1e-6);
  EXPECT_NEAR(sim.pose().x, 2.0, 1e-9);
  EXPECT_NEAR(sim.pose().y, 3.0, 1e-9);
  EXPECT_NEAR(sim.velocity().omega, alpha * t, 1e-6);
  EXPECT_NEAR(sim.velocity().v, 0.0, 1e-9);
}

/// Kinetic energy of the rigid chair from its parts: body M_T at P_c (d behind P), wheels at
/// P +- b across, each spinning (I_w) and turning with the chair (I_m).
double partsKineticEnergy(const wd::State& x, const wd::ChairParams& c) {
  const Eigen::Vector2d vw = wd::bodyVelocity(x.tail<2>(), c);
  const double v = vw(0), w = vw(1), b = c.half_track, d = c.cm_offset;
  const double body = 0.5 * c.total_mass * (v * v + d * d * w * w) + 0.5 * c.body_inertia * w * w;
  const double wheels = 0.5 * c.wheel_mass * (std::pow(v + b * w, 2) + std::pow(v - b * w, 2)) +
                        0.5 * c.wheel_inertia * x.tail<2>().squaredNorm() +
                        c.wheel_inertia_diam * w * w;
  return body + wheels;
}

// With the real offset d the spin also drags P (the body swings out); the work of the wheel
// torques must still equal the kinetic energy of the parts.
TEST(Dynamics, OppositeTorquesWorkEqualsKineticEnergy) {
  const auto chair = test::chair();
  Simulator sim(chair, idealParams(), nullptr);
  const double tau = 5.0;
  sim.applyWheelTorques(tau, -tau, false);
  sim.step(1.5);
  const WheelReading w = sim.readWheels();
  const double work = tau * w.angle(0) - tau * w.angle(1);
  ASSERT_GT(work, 10.0);
  EXPECT_NEAR(partsKineticEnergy(sim.state(), chair), work, 1e-6 * work);
}

TEST(Dynamics, RollingResistanceStopsWithinTheEnergyDistance) {
  const auto chair = test::chair();
  SimParams params = idealParams();
  params.rolling_resistance = true;
  Simulator sim(chair, params, nullptr);
  const double v0 = 1.0;
  ASSERT_TRUE(sim.teleport({0.0, 0.0, 0.0}));
  wd::State moving = sim.state();
  moving.tail<2>() = wd::wheelSpeeds(v0, 0.0, chair);
  sim.setState(moving);
  double min_speed = v0;
  for (int i = 0; i < 1000; ++i) {
    sim.step(0.01);
    min_speed = std::min(min_speed, sim.velocity().v);
  }
  // Kinetic energy 1/2 m_eff v0^2 is spent against the force c_rr m g.
  const double mass = chair.total_mass + 2.0 * chair.wheel_mass;
  const double distance =
      0.5 * forwardInertia(chair) * v0 * v0 / (chair.rolling_resistance * mass * 9.80665);
  EXPECT_NEAR(sim.pose().x, distance, 0.005);
  EXPECT_NEAR(sim.velocity().v, 0.0, 1e-4);
  EXPECT_GE(min_speed, 0.0) << "the chair must not roll back (no oscillation at rest)";
  EXPECT_NEAR(sim.pose().y, 0.0, 1e-9);
}

TEST(Dynamics, RollingResistanceHoldsAChairAtRest) {
  const auto chair = test::chair();
  SimParams params = idealParams();
  params.rolling_resistance = true;
  Simulator sim(chair, params, nullptr);
  const Eigen::Vector3d start = test::asVector(sim.pose());
  sim.step(5.0);
  EXPECT_EQ(test::asVector(sim.pose()), start);
  EXPECT_EQ(test::asVector(sim.velocity()), Eigen::Vector2d::Zero());
}

TEST(Dynamics, TorqueLimitClampsTheCommand) {
  const auto chair = test::chair();
  SimParams params = idealParams();
  params.torque_limit = true;
  Simulator limited(chair, params, nullptr);
  limited.applyWheelTorques(1e4, 1e4, false);
  limited.step(1.0);
  const double a = 2.0 * chair.max_wheel_torque / chair.wheel_radius / forwardInertia(chair);
  EXPECT_NEAR(limited.velocity().v, a, 1e-6);
  EXPECT_DOUBLE_EQ(limited.appliedTorques()(0), chair.max_wheel_torque);
}

TEST(Dynamics, NonFiniteTorquesActAsZero) {
  const auto chair = test::chair();
  Simulator sim(chair, idealParams(), nullptr);
  sim.applyWheelTorques(std::nan(""), std::numeric_limits<double>::infinity(), false);
  sim.step(1.0);
  EXPECT_EQ(test::asVector(sim.velocity()), Eigen::Vector2d::Zero());
  EXPECT_TRUE(sim.state().allFinite());
}

TEST(Dynamics, BrakeStopsAMovingChairAndIgnoresTheCommand) {
  const auto chair = test::chair();
  Simulator sim(chair, idealParams(), nullptr);
  sim.applyWheelTorques(20.0, 20.0, false);
  sim.step(1.0);
  ASSERT_GT(sim.velocity().v, 0.3);
  sim.applyWheelTorques(20.0, 20.0, true);
  sim.step(3.0);
  EXPECT_NEAR(sim.velocity().v, 0.0, 1e-3);
}

TEST(Dynamics, StepSizeDoesNotChangeTheTrajectory) {
  const auto chair = test::chair();
  Simulator coarse(chair, idealParams(), nullptr), fine(chair, idealParams(), nullptr);
  for (auto* s : {&coarse, &fine}) s->applyWheelTorques(8.0, 3.0, false);
  coarse.step(2.0);
  for (int i = 0; i < 400; ++i) fine.step(0.005);
  EXPECT_LT((test::asVector(coarse.pose()) - test::asVector(fine.pose())).norm(), 1e-9);
}

TEST(Dynamics, SlipNoiseMovesTheTruthAwayFromTheEncoders) {
  const auto chair = test::chair();
  SimParams params = idealParams();
  params.slip_noise = 0.05;
  Simulator slipping(chair, params, nullptr), ideal(chair, idealParams(), nullptr);
  for (auto* s : {&slipping, &ideal}) {
    s->applyWheelTorques(10.0, 10.0, false);
    s->step(3.0);
  }
  EXPECT_EQ(slipping.readWheels().angle, ideal.readWheels().angle);  // encoders agree
  const double moved = ideal.pose().x;
  // Heading error std: slip sqrt(2 * moved) / (2 b); require a visible, bounded deviation.
  const double sigma = params.slip_noise * std::sqrt(2.0 * moved) / (2.0 * chair.half_track);
  EXPECT_GT(std::abs(slipping.pose().yaw) + std::abs(slipping.pose().x - moved), 1e-4);
  EXPECT_LT(std::abs(slipping.pose().yaw), 5.0 * sigma);
}

}  // namespace
}  // namespace wheelchair_sim
