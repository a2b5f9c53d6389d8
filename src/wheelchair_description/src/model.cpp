// The paper's model, section 3. Derivations that correct the paper's typos are in README.md.
#include <wheelchair_description/model.h>

#include <Eigen/Cholesky>

#include <cmath>

namespace wheelchair_description {
namespace {

/// c = r / (2b), the common factor of S(q) (eq. 11).
double sFactor(const ChairParams& p) { return p.wheel_radius / (2.0 * p.half_track); }

Vector5 configuration(const State& x) { return x.head<5>(); }
Eigen::Vector2d wheelRates(const State& x) { return x.tail<2>(); }

}  // namespace

// Eq. 8 (rows: eq. 4 no lateral slip at P, eq. 5 right wheel rolls, eq. 6 left wheel rolls).
Matrix35 constraintMatrix(const Vector5& q, const ChairParams& p) {
  const double s = std::sin(q(kTheta)), c = std::cos(q(kTheta));
  const double b = p.half_track, d = p.cm_offset, r = p.wheel_radius;
  Matrix35 a;
  a << -s, c, d, 0, 0,   //
      -c, -s, -b, r, 0,  //
      -c, -s, b, 0, r;
  return a;
}

// Eq. 11.
Matrix52 nullSpaceBasis(const Vector5& q, const ChairParams& p) {
  const double s = std::sin(q(kTheta)), c = std::cos(q(kTheta));
  const double b = p.half_track, d = p.cm_offset, k = sFactor(p);
  Matrix52 m;
  m << k * (b * c + d * s), k * (b * c - d * s),  //
      k * (b * s - d * c), k * (b * s + d * c),   //
      k, -k,                                      //
      1, 0,                                       //
      0, 1;
  return m;
}

// d/dt of eq. 11: only theta varies.
Matrix52 nullSpaceBasisDot(const Vector5& q, double theta_dot, const ChairParams& p) {
  const double s = std::sin(q(kTheta)), c = std::cos(q(kTheta));
  const double b = p.half_track, d = p.cm_offset, k = sFactor(p) * theta_dot;
  Matrix52 m = Matrix52::Zero();
  m(0, 0) = k * (-b * s + d * c);
  m(0, 1) = k * (-b * s - d * c);
  m(1, 0) = k * (b * c + d * s);
  m(1, 1) = k * (b * c - d * s);
  return m;
}

// Eq. 13. M_I6 = I_T + 2 m_w (d^2 + b^2) + 2 I_m: the paper's "2 m_w l^2 + I_w" with
// l^2 = d^2 + b^2 (wheel centre to P_c) and both wheels' inertia about a diameter.
Matrix5 inertiaMatrix(const Vector5& q, const ChairParams& p) {
  const double s = std::sin(q(kTheta)), c = std::cos(q(kTheta));
  const double mw = p.wheel_mass, d = p.cm_offset, b = p.half_track;
  const double m = p.total_mass + 2.0 * mw;
  Matrix5 mi = Matrix5::Zero();
  mi(0, 0) = m;
  mi(1, 1) = m;
  mi(0, 2) = mi(2, 0) = -2.0 * mw * d * s;
  mi(1, 2) = mi(2, 1) = 2.0 * mw * d * c;
  mi(2, 2) = p.body_inertia + 2.0 * mw * (d * d + b * b) + 2.0 * p.wheel_inertia_diam;
  mi(3, 3) = p.wheel_inertia;
  mi(4, 4) = p.wheel_inertia;
  return mi;
}

// Eq. 13: V = [-2 m_w d theta_dot^2 cos(theta), -2 m_w d theta_dot^2 sin(theta), 0, 0, 0].
Vector5 coriolisVector(const Vector5& q, const Vector5& q_dot, const ChairParams& p) {
  const double w2 = q_dot(kTheta) * q_dot(kTheta);
  const double k = -2.0 * p.wheel_mass * p.cm_offset * w2;
  Vector5 v = Vector5::Zero();
  v(0) = k * std::cos(q(kTheta));
  v(1) = k * std::sin(q(kTheta));
  return v;
}

// Eq. 13.
Matrix52 inputMatrix() {
  Matrix52 b = Matrix52::Zero();
  b(3, 0) = 1.0;
  b(4, 1) = 1.0;
  return b;
}

// Eq. 14.
Eigen::Matrix2d dynamicsF1(const Vector5& q, const ChairParams& p) {
  const Matrix52 s = nullSpaceBasis(q, p);
  return s.transpose() * inertiaMatrix(q, p) * s;
}

// Eq. 14.
Eigen::Vector2d dynamicsF2(const Vector5& q, const Eigen::Vector2d& eta, const ChairParams& p) {
  const Matrix52 s = nullSpaceBasis(q, p);
  const Vector5 q_dot = s * eta;
  const Matrix52 s_dot = nullSpaceBasisDot(q, q_dot(kTheta), p);
  return s.transpose() * (inertiaMatrix(q, p) * s_dot * eta + coriolisVector(q, q_dot, p));
}

// Eq. 14 (S^T B = I, S^T A^T lambda = 0).
Eigen::Vector2d wheelAcceleration(const Vector5& q, const Eigen::Vector2d& eta,
                                  const Eigen::Vector2d& tau, const ChairParams& p) {
  return dynamicsF1(q, p).ldlt().solve(tau - dynamicsF2(q, eta, p));
}

// Eq. 15.
State stateDerivative(const State& x, const Eigen::Vector2d& tau, const ChairParams& p) {
  const Vector5 q = configuration(x);
  const Eigen::Vector2d eta = wheelRates(x);
  State x_dot;
  x_dot.head<5>() = nullSpaceBasis(q, p) * eta;
  x_dot.tail<2>() = wheelAcceleration(q, eta, tau, p);
  return x_dot;
}

State integrateRK2(const State& x, const Eigen::Vector2d& tau, double dt, const ChairParams& p) {
  const State k1 = stateDerivative(x, tau, p);
  const State k2 = stateDerivative(x + 0.5 * dt * k1, tau, p);
  return x + dt * k2;
}

State integrateRK4(const State& x, const Eigen::Vector2d& tau, double dt, const ChairParams& p) {
  const State k1 = stateDerivative(x, tau, p);
  const State k2 = stateDerivative(x + 0.5 * dt * k1, tau, p);
  const State k3 = stateDerivative(x + 0.5 * dt * k2, tau, p);
  const State k4 = stateDerivative(x + dt * k3, tau, p);
  return x + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

double kineticEnergy(const State& x, const ChairParams& p) {
  const Eigen::Vector2d eta = wheelRates(x);
  return 0.5 * eta.dot(dynamicsF1(configuration(x), p) * eta);
}

// Eq. 10-11 at P: wheelchair_core's, in the model's [right, left] vectors.
Eigen::Vector2d bodyVelocity(const Eigen::Vector2d& eta, const ChairParams& p) {
  const wheelchair_core::BodyTwist twist =
      wheelchair_core::bodyTwist({eta(0), eta(1)}, p.wheelBase());
  return {twist.v, twist.omega};
}

Eigen::Vector2d wheelSpeeds(double v, double omega, const ChairParams& p) {
  const wheelchair_core::WheelRates rates = wheelchair_core::wheelRates({v, omega}, p.wheelBase());
  return {rates.right, rates.left};
}

Eigen::Vector3d axlePose(const State& x, const ChairParams& p) {
  const double th = x(kTheta);
  return {x(kXc) + p.cm_offset * std::cos(th), x(kYc) + p.cm_offset * std::sin(th), th};
}

State stateAtAxlePose(double x, double y, double theta, const ChairParams& p) {
  State s = State::Zero();
  s(kXc) = x - p.cm_offset * std::cos(theta);
  s(kYc) = y - p.cm_offset * std::sin(theta);
  s(kTheta) = theta;
  return s;
}

}  // namespace wheelchair_description
