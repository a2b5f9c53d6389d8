// Eqs. 18-21: the decoupling matrix, its derivative and the linearizing law, against finite
// differences of the model and the closed form det Phi = -2 b L c^2.
#include <wheelchair_controller/linearization.h>
#include <wheelchair_controller/torque_saturation.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>

namespace wc = wheelchair_controller;
namespace wd = wheelchair_description;

namespace {

wd::ChairParams chair() { return wd::test::shippedChair(); }

wd::State someState() {
  wd::State x;
  x << 0.3, -0.2, 0.7, 1.0, 2.0, 3.0, 1.5;
  return x;
}

}  // namespace

TEST(Linearization, DecouplingDeterminantIsMinusTwoBLcSquared) {
  const wd::ChairParams p = chair();
  const double c = p.wheel_radius / (2.0 * p.half_track);
  for (double th : {0.0, 0.5, 2.0, -2.5}) {
    wd::Vector5 q = someState().head<5>();
    q(wd::kTheta) = th;
    EXPECT_NEAR(wc::decouplingMatrix(q, p).determinant(), -2.0 * p.half_track * p.lookahead * c * c,
                1e-12);
  }
}

TEST(Linearization, InvertibleIffLookaheadNonZero) {
  wd::ChairParams p = chair();
  const wd::Vector5 q = someState().head<5>();
  for (double l : {0.05, 0.15, 0.5, -0.1}) {
    p.lookahead = l;
    EXPECT_GT(std::abs(wc::decouplingMatrix(q, p).determinant()), 1e-6) << "L=" << l;
  }
  p.lookahead = 0.0;  // P_l on the axle: its lateral velocity cannot be commanded
  EXPECT_NEAR(wc::decouplingMatrix(q, p).determinant(), 0.0, 1e-15);
  Eigen::FullPivLU<Eigen::Matrix2d> lu(wc::decouplingMatrix(q, p));
  EXPECT_EQ(lu.rank(), 1);
}

TEST(Linearization, OutputVelocityMatchesFiniteDifferenceOfOutput) {
  const wd::ChairParams p = chair();
  const wd::State x = someState();
  const double h = 1e-6;
  const wd::State x2 = wd::integrateRK4(x, Eigen::Vector2d::Zero(), h, p);
  const Eigen::Vector2d fd =
      (wc::outputPoint(x2.head<5>(), p) - wc::outputPoint(x.head<5>(), p)) / h;
  EXPECT_LT((fd - wc::outputVelocity(x.head<5>(), x.tail<2>(), p)).norm(), 1e-5);
}

TEST(Linearization, DecouplingDotMatchesFiniteDifference) {
  const wd::ChairParams p = chair();
  const wd::State x = someState();
  const double h = 1e-6;
  const wd::State x2 = wd::integrateRK4(x, Eigen::Vector2d::Zero(), h, p);
  const Eigen::Matrix2d fd =
      (wc::decouplingMatrix(x2.head<5>(), p) - wc::decouplingMatrix(x.head<5>(), p)) / h;
  EXPECT_LT((fd - wc::decouplingMatrixDot(x.head<5>(), x.tail<2>(), p)).norm(), 1e-5);
}

TEST(Linearization, ComputedTorqueGivesCommandedOutputAcceleration) {
  // tau = f1 u + f2 with u from eq. 21 must make y_ddot = v on the model (eq. 15).
  const wd::ChairParams p = chair();
  const wd::State x = someState();
  const Eigen::Vector2d v(0.3, -0.2);
  const Eigen::Vector2d u = wc::linearizingInput(x.head<5>(), x.tail<2>(), v, p);
  const Eigen::Vector2d tau = wc::computedTorque(x.head<5>(), x.tail<2>(), u, p);
  const double h = 1e-4;
  const auto y_at = [&](double t) {
    return wc::outputPoint(wd::integrateRK4(x, tau, t, p).head<5>(), p);
  };
  const Eigen::Vector2d y_ddot = (y_at(h) - 2.0 * y_at(0.0) + y_at(-h)) / (h * h);
  EXPECT_LT((y_ddot - v).norm(), 1e-4);
}

TEST(Linearization, DynamicsDoNotDependOnPose) {
  // The controlled stop uses f1, f2 at q = 0: check rotation/translation invariance.
  const wd::ChairParams p = chair();
  const wd::State x = someState();
  const Eigen::Vector2d eta = x.tail<2>();
  EXPECT_LT((wd::dynamicsF1(x.head<5>(), p) - wd::dynamicsF1(wd::Vector5::Zero(), p)).norm(),
            1e-12);
  EXPECT_LT(
      (wd::dynamicsF2(x.head<5>(), eta, p) - wd::dynamicsF2(wd::Vector5::Zero(), eta, p)).norm(),
      1e-12);
}

TEST(Saturation, NeverExceedsTheLimitByRounding) {
  // The base driver rejects |tau| > max_torque: scaling must not overshoot by one ulp.
  for (double big = 50.0 + 1e-3; big < 5000.0; big *= 1.37) {
    for (double other : {-big, -0.3 * big, 0.7 * big, big}) {
      const wc::SaturatedTorque s = wc::saturateTorque(Eigen::Vector2d(big, other), 50.0);
      EXPECT_LE(s.torque.cwiseAbs().maxCoeff(), 50.0) << big << " " << other;
      EXPECT_NEAR(s.torque(1) / s.torque(0), other / big, 1e-12);
    }
  }
}

TEST(Saturation, ScalesBothWheelsAndKeepsDirection) {
  const Eigen::Vector2d tau(80.0, 20.0);
  const wc::SaturatedTorque s = wc::saturateTorque(tau, 50.0);
  EXPECT_DOUBLE_EQ(s.torque(0), 50.0);
  EXPECT_DOUBLE_EQ(s.torque(1), 12.5);  // not clipped to 20: ratio 4:1 kept
  EXPECT_DOUBLE_EQ(s.scale, 50.0 / 80.0);
  EXPECT_NEAR(std::atan2(s.torque(1), s.torque(0)), std::atan2(tau(1), tau(0)), 1e-12);
  const wc::SaturatedTorque n = wc::saturateTorque(Eigen::Vector2d(-30.0, 10.0), 50.0);
  EXPECT_EQ(n.torque, Eigen::Vector2d(-30.0, 10.0));
  EXPECT_DOUBLE_EQ(n.scale, 1.0);
}
