// The paper's kinematic and dynamic model of a differential-drive wheelchair (section 3),
// each equation in one named function. ROS-free (Eigen only).
//
// Generalized coordinates q = [x_c, y_c, theta, psi_r, psi_l] (eq. 9): P_c is the centre of
// mass of body + rider, P = P_c + d (cos theta, sin theta) the axle centre, psi_r/psi_l the
// wheel rotation angles. Velocities eta = [psi_r_dot, psi_l_dot] (eq. 11). State x = [q; eta].
#pragma once

#include <wheelchair_description/chair_params.h>

#include <Eigen/Core>

namespace wheelchair_description {

using Vector5 = Eigen::Matrix<double, 5, 1>;
using Matrix5 = Eigen::Matrix<double, 5, 5>;
using Matrix35 = Eigen::Matrix<double, 3, 5>;
using Matrix52 = Eigen::Matrix<double, 5, 2>;
using State = Eigen::Matrix<double, 7, 1>;  ///< x = [q; eta] (eq. 15)

/// Indices into q and x.
enum Coord { kXc = 0, kYc = 1, kTheta = 2, kPsiR = 3, kPsiL = 4, kEtaR = 5, kEtaL = 6 };

/// Eq. 8: constraint matrix A(q) of A(q) q_dot = 0 (eq. 7): no lateral slip at P (eq. 4),
/// rolling without slipping of the right (eq. 5) and left (eq. 6) wheels.
Matrix35 constraintMatrix(const Vector5& q, const ChairParams& p);

/// Eq. 11: S(q), a basis of the null space of A(q), q_dot = S(q) eta (eq. 10).
/// c = r / (2b) (the paper's "r/2h" is a typo for b).
Matrix52 nullSpaceBasis(const Vector5& q, const ChairParams& p);

/// Time derivative of S(q) along q_dot (only theta varies): dS/dtheta * theta_dot.
Matrix52 nullSpaceBasisDot(const Vector5& q, double theta_dot, const ChairParams& p);

/// Eq. 13: inertia matrix M_I(q).
Matrix5 inertiaMatrix(const Vector5& q, const ChairParams& p);

/// Eq. 13: centripetal and Coriolis vector V(q, q_dot).
Vector5 coriolisVector(const Vector5& q, const Vector5& q_dot, const ChairParams& p);

/// Eq. 13: input matrix B (torques act on the wheel coordinates).
Matrix52 inputMatrix();

/// Eq. 14: f1 = S^T M_I S (2x2, symmetric positive definite).
Eigen::Matrix2d dynamicsF1(const Vector5& q, const ChairParams& p);

/// Eq. 14: f2 = S^T M_I S_dot eta + S^T V.
Eigen::Vector2d dynamicsF2(const Vector5& q, const Eigen::Vector2d& eta, const ChairParams& p);

/// Eq. 14: eta_dot = f1^{-1} (tau - f2), tau = [tau_r, tau_l].
Eigen::Vector2d wheelAcceleration(const Vector5& q, const Eigen::Vector2d& eta,
                                  const Eigen::Vector2d& tau, const ChairParams& p);

/// Eq. 15: x_dot = [S eta; f1^{-1}(tau - f2)].
State stateDerivative(const State& x, const Eigen::Vector2d& tau, const ChairParams& p);

/// One step of the second-order Runge-Kutta (midpoint) method, as in the paper (section 4).
State integrateRK2(const State& x, const Eigen::Vector2d& tau, double dt, const ChairParams& p);

/// One step of the classic fourth-order Runge-Kutta method (the simulator's integrator).
State integrateRK4(const State& x, const Eigen::Vector2d& tau, double dt, const ChairParams& p);

/// Kinetic energy T = 1/2 eta^T f1 eta (conserved with zero torque and no friction).
double kineticEnergy(const State& x, const ChairParams& p);

/// Eq. 10-11 (wheelchair_core::bodyTwist): forward speed of the axle centre P and yaw rate
/// from wheel speeds eta = [psi_r_dot, psi_l_dot]: (v, omega).
Eigen::Vector2d bodyVelocity(const Eigen::Vector2d& eta, const ChairParams& p);

/// The inverse (wheelchair_core::wheelRates): wheel speeds [psi_r_dot, psi_l_dot] that give
/// forward speed v at P and yaw rate omega.
Eigen::Vector2d wheelSpeeds(double v, double omega, const ChairParams& p);

/// Pose of the axle centre P (the base_link origin) from the state: (x, y, theta).
Eigen::Vector3d axlePose(const State& x, const ChairParams& p);

/// State at rest whose axle centre P is at (x, y) with heading theta.
State stateAtAxlePose(double x, double y, double theta, const ChairParams& p);

}  // namespace wheelchair_description
