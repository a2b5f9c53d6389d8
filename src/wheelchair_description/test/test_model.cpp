// The model (eqs. 4-15) against the physics it must obey.
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description/model.h>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include <random>

using namespace wheelchair_description;

namespace {

ChairParams chair() { return loadChairParams(defaultChairParamsPath()); }

}  // namespace

TEST(Model, ConstraintTimesNullSpaceIsZeroForRandomConfigurations) {  // A(q) S(q) = 0
  const ChairParams p = chair();
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (int i = 0; i < 1000; ++i) {
    Vector5 q;
    for (int j = 0; j < 5; ++j) q(j) = u(rng);
    EXPECT_LT((constraintMatrix(q, p) * nullSpaceBasis(q, p)).norm(), 1e-12);
  }
}

TEST(Model, EqualTorquesFromRestDriveStraight) {
  const ChairParams p = chair();
  State x = stateAtAxlePose(1.0, 2.0, 0.3, p);
  for (int i = 0; i < 2000; ++i) x = integrateRK4(x, Eigen::Vector2d(5.0, 5.0), 1e-3, p);
  const Eigen::Vector3d pose = axlePose(x, p);
  EXPECT_NEAR(pose.z(), 0.3, 1e-12);  // no rotation
  const double along = (pose.x() - 1.0) * std::cos(0.3) + (pose.y() - 2.0) * std::sin(0.3);
  const double across = -(pose.x() - 1.0) * std::sin(0.3) + (pose.y() - 2.0) * std::cos(0.3);
  EXPECT_GT(along, 0.1);
  EXPECT_NEAR(across, 0.0, 1e-12);
  // Straight line: f1 is constant, so eta_dot = f1^{-1} tau exactly; distance = r a t^2 / 2.
  const Eigen::Vector2d acc = dynamicsF1(x.head<5>(), p).ldlt().solve(Eigen::Vector2d(5.0, 5.0));
  EXPECT_NEAR(along, 0.5 * p.wheel_radius * acc(0) * 4.0, 1e-9);
}

TEST(Model, OppositeTorquesRotateInPlaceWhenTheCentreOfMassIsOnTheAxle) {
  ChairParams p = chair();
  p.cm_offset = 0.0;  // d = 0: nothing couples rotation into translation
  State x = stateAtAxlePose(0.0, 0.0, 0.0, p);
  for (int i = 0; i < 2000; ++i) x = integrateRK4(x, Eigen::Vector2d(4.0, -4.0), 1e-3, p);
  const Eigen::Vector3d pose = axlePose(x, p);
  EXPECT_GT(pose.z(), 0.1);  // right wheel forward -> counter-clockwise (REP-103)
  EXPECT_NEAR(pose.x(), 0.0, 1e-12);
  EXPECT_NEAR(pose.y(), 0.0, 1e-12);
  // Pure rotation: theta = c * (psi_r - psi_l) with the wheels turning in opposite senses.
  EXPECT_NEAR(x(kPsiR), -x(kPsiL), 1e-12);
}

TEST(Model, KineticEnergyIsConservedWithoutTorque) {
  const ChairParams p = chair();
  State x = stateAtAxlePose(0.0, 0.0, 0.0, p);
  x(kEtaR) = 6.0;
  x(kEtaL) = 1.0;  // a curve
  const double e0 = kineticEnergy(x, p);
  for (int i = 0; i < 10000; ++i) x = integrateRK4(x, Eigen::Vector2d::Zero(), 1e-3, p);
  EXPECT_NEAR(kineticEnergy(x, p), e0, 1e-8 * e0);
}

TEST(Model, ConstraintsHoldAlongLongRandomTorqueRun) {
  const ChairParams p = chair();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-p.max_wheel_torque, p.max_wheel_torque);
  State x = stateAtAxlePose(0.0, 0.0, 0.0, p);
  Eigen::Vector2d tau(0, 0);
  for (int i = 0; i < 60000; ++i) {
    if (i % 100 == 0) tau = Eigen::Vector2d(u(rng), u(rng)) * 0.2;
    x = integrateRK2(x, tau, 1e-3, p);
    const Vector5 q_dot = stateDerivative(x, tau, p).head<5>();
    ASSERT_LT((constraintMatrix(x.head<5>(), p) * q_dot).norm(), 1e-9) << "step " << i;
  }
}
