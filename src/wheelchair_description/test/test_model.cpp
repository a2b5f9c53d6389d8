// The model (eqs. 4-15) against the physics it must obey.
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description/model.h>
#include <wheelchair_description_testing/chair_file.h>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>
#include <random>

using namespace wheelchair_description;

namespace {

ChairParams chair() { return test::shippedChair(); }

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

namespace {

/// A random configuration q with angles in [-pi, pi] and positions in [-10, 10].
Vector5 randomConfiguration(std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(-10.0, 10.0), ang(-M_PI, M_PI);
  Vector5 q;
  q << pos(rng), pos(rng), ang(rng), ang(rng), ang(rng);
  return q;
}

/// Kinetic energy summed over the parts, written independently of eq. 13: body + rider (mass
/// M_T, inertia I_T) at P_c; each wheel (mass m_w) at P +- b n with P = P_c + d h, spinning
/// about its axle (I_w) and turning with the chair about a diameter (I_m).
double kineticEnergyOfParts(const Vector5& q, const Vector5& q_dot, const ChairParams& p) {
  const double th = q(kTheta), w = q_dot(kTheta);
  const Eigen::Vector2d h(std::cos(th), std::sin(th)), n(-std::sin(th), std::cos(th));
  const Eigen::Vector2d vc(q_dot(kXc), q_dot(kYc));
  double t = 0.5 * p.total_mass * vc.squaredNorm() + 0.5 * p.body_inertia * w * w;
  for (double side : {-1.0, 1.0}) {
    // Wheel centre: P_c + d h + side b n; its velocity: vc + w (d n - side b h).
    const Eigen::Vector2d vw = vc + w * (p.cm_offset * n - side * p.half_track * h);
    t += 0.5 * p.wheel_mass * vw.squaredNorm() + 0.5 * p.wheel_inertia_diam * w * w;
  }
  t += 0.5 * p.wheel_inertia * (q_dot(kPsiR) * q_dot(kPsiR) + q_dot(kPsiL) * q_dot(kPsiL));
  return t;
}

/// The inertia matrix of kineticEnergyOfParts by polarization: M_ij = T(e_i + e_j) - T(e_i) -
/// T(e_j) for the quadratic form T = q_dot^T M q_dot / 2 (exact, no differentiation).
Matrix5 inertiaOfParts(const Vector5& q, const ChairParams& p) {
  Matrix5 m;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const Vector5 ei = Vector5::Unit(i), ej = Vector5::Unit(j);
      m(i, j) = kineticEnergyOfParts(q, ei + ej, p) - kineticEnergyOfParts(q, ei, p) -
                kineticEnergyOfParts(q, ej, p);
      if (i == j) m(i, j) = 2.0 * kineticEnergyOfParts(q, ei, p);
    }
  return m;
}

/// The configurations of a curved run under constant unequal torques, RK2 or RK4 with step dt.
State curvedRun(State (*step)(const State&, const Eigen::Vector2d&, double, const ChairParams&),
                double dt, const ChairParams& p) {
  State x = stateAtAxlePose(0.0, 0.0, 0.0, p);
  x(kEtaR) = 4.0;
  x(kEtaL) = 2.0;
  const int steps = static_cast<int>(std::lround(2.0 / dt));
  for (int i = 0; i < steps; ++i) x = step(x, Eigen::Vector2d(20.0, -10.0), dt, p);
  return x;
}

}  // namespace

TEST(Model, F1IsSymmetricPositiveDefinite) {
  const ChairParams p = chair();
  std::mt19937 rng(3);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Matrix2d f1 = dynamicsF1(randomConfiguration(rng), p);
    EXPECT_LT((f1 - f1.transpose()).norm(), 1e-12 * f1.norm());
    EXPECT_EQ(f1.ldlt().info(), Eigen::Success);
    // Sylvester's criterion for a 2x2 matrix.
    EXPECT_GT(f1(0, 0), 0.0);
    EXPECT_GT(f1.determinant(), 0.0);
  }
}

TEST(Model, InertiaMatrixIsTheKineticEnergyOfTheParts) {  // eq. 13, M_I6 corrected
  const ChairParams p = chair();
  std::mt19937 rng(5);
  for (int i = 0; i < 200; ++i) {
    const Vector5 q = randomConfiguration(rng);
    EXPECT_LT((inertiaMatrix(q, p) - inertiaOfParts(q, p)).norm(), 1e-9) << "q = " << q.transpose();
  }
}

TEST(Model, CoriolisVectorFollowsFromTheLagrangian) {  // eq. 12 -> V of eq. 13
  // d/dt(dT/dq_dot) - dT/dq = M q_ddot + (dM/dtheta theta_dot) q_dot - 1/2 q_dot^T dM/dq q_dot,
  // so V = (dM/dtheta theta_dot) q_dot - e_theta q_dot^T (dM/dtheta) q_dot / 2 (M depends on
  // theta only), with dM/dtheta by central differences of the parts' inertia.
  const ChairParams p = chair();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  const double h = 1e-5;
  for (int i = 0; i < 100; ++i) {
    const Vector5 q = randomConfiguration(rng);
    Vector5 q_dot;
    for (int j = 0; j < 5; ++j) q_dot(j) = u(rng);
    const Vector5 dq = h * Vector5::Unit(kTheta);
    const Matrix5 dm = (inertiaOfParts(q + dq, p) - inertiaOfParts(q - dq, p)) / (2.0 * h);
    Vector5 expected = dm * q_dot * q_dot(kTheta);
    expected(kTheta) -= 0.5 * q_dot.dot(dm * q_dot);
    EXPECT_LT((coriolisVector(q, q_dot, p) - expected).norm(), 1e-6 * (1.0 + expected.norm()));
  }
}

TEST(Model, PowerOfTheTorquesIsTheRateOfKineticEnergy) {  // dT/dt = tau . eta (eq. 14's sign)
  ChairParams p = chair();
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (double d : {p.cm_offset, -0.1, 0.0}) {
    p.cm_offset = d;
    for (int i = 0; i < 50; ++i) {
      State x;
      x.head<5>() = randomConfiguration(rng);
      x(kEtaR) = u(rng);
      x(kEtaL) = u(rng);
      const Eigen::Vector2d tau(10.0 * u(rng), 10.0 * u(rng));
      const State x_dot = stateDerivative(x, tau, p);
      const double h = 1e-6;
      const double rate =
          (kineticEnergy(x + h * x_dot, p) - kineticEnergy(x - h * x_dot, p)) / (2.0 * h);
      EXPECT_NEAR(rate, tau.dot(x.tail<2>()), 1e-5 * (1.0 + std::abs(rate))) << "d = " << d;
    }
  }
}

TEST(Model, StraightAccelerationIsNewtonsLaw) {
  // Equal torques tau on both wheels: 2 tau / r = (M_T + 2 m_w + 2 I_w / r^2) a.
  const ChairParams p = chair();
  const double tau = 7.0, r = p.wheel_radius;
  const double a =
      2.0 * tau / r / (p.total_mass + 2.0 * p.wheel_mass + 2.0 * p.wheel_inertia / (r * r));
  const State x = stateAtAxlePose(0.5, -1.0, 1.2, p);
  const Eigen::Vector2d eta_dot = stateDerivative(x, Eigen::Vector2d(tau, tau), p).tail<2>();
  EXPECT_NEAR(eta_dot(0), a / r, 1e-12);
  EXPECT_NEAR(eta_dot(1), a / r, 1e-12);
}

TEST(Model, RotationInPlaceAccelerationIsEulersLaw) {
  // d = 0, torques +tau/-tau: the wheel forces 2 tau / r act on the lever b; the yaw inertia
  // is I_T + 2 m_w b^2 + 2 I_m plus the wheels' spin inertia seen through psi = b theta / r.
  ChairParams p = chair();
  p.cm_offset = 0.0;
  const double tau = 3.0, r = p.wheel_radius, b = p.half_track;
  const double inertia = p.body_inertia + 2.0 * p.wheel_mass * b * b + 2.0 * p.wheel_inertia_diam +
                         2.0 * p.wheel_inertia * b * b / (r * r);
  const double alpha = 2.0 * tau * b / r / inertia;
  const State x = stateAtAxlePose(0.0, 0.0, -0.4, p);
  const State x_dot = stateDerivative(x, Eigen::Vector2d(tau, -tau), p);
  const double theta_ddot = (p.wheel_radius / (2.0 * p.half_track)) * (x_dot(kEtaR) - x_dot(kEtaL));
  EXPECT_NEAR(theta_ddot, alpha, 1e-12);
}

TEST(Model, Rk2IsSecondOrderAndRk4FourthOrderOnACurve) {
  const ChairParams p = chair();
  const State reference = curvedRun(integrateRK4, 1e-4, p);
  using Step = State (*)(const State&, const Eigen::Vector2d&, double, const ChairParams&);
  const auto error = [&](Step step, double dt) {
    return (curvedRun(step, dt, p).head<3>() - reference.head<3>()).norm();
  };
  const double rk2_order = std::log2(error(integrateRK2, 0.02) / error(integrateRK2, 0.01));
  const double rk4_order = std::log2(error(integrateRK4, 0.04) / error(integrateRK4, 0.02));
  EXPECT_NEAR(rk2_order, 2.0, 0.2);
  EXPECT_NEAR(rk4_order, 4.0, 0.3);
}

TEST(Model, BodyVelocityAndWheelSpeedsAreInverseAndMatchS) {
  const ChairParams p = chair();
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int i = 0; i < 100; ++i) {
    const double v = u(rng), omega = u(rng);
    const Eigen::Vector2d eta = wheelSpeeds(v, omega, p);
    EXPECT_LT((bodyVelocity(eta, p) - Eigen::Vector2d(v, omega)).norm(), 1e-12);
    // The axle centre P moves at v along the heading and turns at omega (eq. 10, 11).
    State x = stateAtAxlePose(u(rng), u(rng), 3.0 * u(rng), p);
    x.tail<2>() = eta;
    const double h = 1e-6;
    const State x_dot = stateDerivative(x, Eigen::Vector2d::Zero(), p);
    const Eigen::Vector3d pose_dot =
        (axlePose(x + h * x_dot, p) - axlePose(x - h * x_dot, p)) / (2 * h);
    const double th = x(kTheta);
    EXPECT_NEAR(pose_dot.x(), v * std::cos(th), 1e-6);
    EXPECT_NEAR(pose_dot.y(), v * std::sin(th), 1e-6);
    EXPECT_NEAR(pose_dot.z(), omega, 1e-6);
  }
}
