#include <wheelchair_controller/linearization.h>

#include <Eigen/LU>

#include <cmath>

namespace wheelchair_controller {
namespace wd = wheelchair_description;

namespace {
/// d + ell: distance from P_c to the output point (ell = L: P_l).
double outputOffset(const ChairParams& p, double ell) { return p.cm_offset + ell; }
}  // namespace

// Eq. 18.
Eigen::Vector2d outputPoint(const Vector5& q, const ChairParams& p) {
  return outputPoint(q, p, p.lookahead);
}

Eigen::Vector2d outputPoint(const Vector5& q, const ChairParams& p, double ell) {
  const double th = q(wd::kTheta), k = outputOffset(p, ell);
  return {q(wd::kXc) + k * std::cos(th), q(wd::kYc) + k * std::sin(th)};
}

Matrix25 outputJacobian(const Vector5& q, const ChairParams& p) {
  return outputJacobian(q, p, p.lookahead);
}

Matrix25 outputJacobian(const Vector5& q, const ChairParams& p, double ell) {
  const double th = q(wd::kTheta), k = outputOffset(p, ell);
  Matrix25 j = Matrix25::Zero();
  j(0, 0) = 1.0;
  j(1, 1) = 1.0;
  j(0, 2) = -k * std::sin(th);
  j(1, 2) = k * std::cos(th);
  return j;
}

// Eq. 19.
Eigen::Matrix2d decouplingMatrix(const Vector5& q, const ChairParams& p) {
  return decouplingMatrix(q, p, p.lookahead);
}

Eigen::Matrix2d decouplingMatrix(const Vector5& q, const ChairParams& p, double ell) {
  return outputJacobian(q, p, ell) * wd::nullSpaceBasis(q, p);
}

Eigen::Matrix2d decouplingMatrixDot(const Vector5& q, const Eigen::Vector2d& eta,
                                    const ChairParams& p) {
  return decouplingMatrixDot(q, eta, p, p.lookahead);
}

Eigen::Matrix2d decouplingMatrixDot(const Vector5& q, const Eigen::Vector2d& eta,
                                    const ChairParams& p, double ell) {
  const wd::Matrix52 s = wd::nullSpaceBasis(q, p);
  const double th = q(wd::kTheta), k = outputOffset(p, ell);
  const double th_dot = (s * eta)(wd::kTheta);
  Matrix25 j_dot = Matrix25::Zero();
  j_dot(0, 2) = -k * std::cos(th) * th_dot;
  j_dot(1, 2) = -k * std::sin(th) * th_dot;
  return j_dot * s + outputJacobian(q, p, ell) * wd::nullSpaceBasisDot(q, th_dot, p);
}

// Eq. 19, first line.
Eigen::Vector2d outputVelocity(const Vector5& q, const Eigen::Vector2d& eta, const ChairParams& p) {
  return outputVelocity(q, eta, p, p.lookahead);
}

Eigen::Vector2d outputVelocity(const Vector5& q, const Eigen::Vector2d& eta, const ChairParams& p,
                               double ell) {
  return decouplingMatrix(q, p, ell) * eta;
}

// Eq. 21: y_ddot = Phi_dot eta + Phi u = v  =>  u = Phi^{-1} (v - Phi_dot eta).
Eigen::Vector2d linearizingInput(const Vector5& q, const Eigen::Vector2d& eta,
                                 const Eigen::Vector2d& v, const ChairParams& p) {
  return linearizingInput(q, eta, v, p, p.lookahead);
}

Eigen::Vector2d linearizingInput(const Vector5& q, const Eigen::Vector2d& eta,
                                 const Eigen::Vector2d& v, const ChairParams& p, double ell) {
  return decouplingMatrix(q, p, ell).partialPivLu().solve(v - decouplingMatrixDot(q, eta, p, ell) *
                                                                  eta);
}

// y_dot = v h + ell theta_dot n  =>  n . y_dot = ell theta_dot.
double zeroDynamicsHeadingRate(double theta, const Eigen::Vector2d& y_dot_ref, double ell) {
  return (-std::sin(theta) * y_dot_ref.x() + std::cos(theta) * y_dot_ref.y()) / ell;
}

// Section 3.3: tau = f1 u + f2.
Eigen::Vector2d computedTorque(const Vector5& q, const Eigen::Vector2d& eta,
                               const Eigen::Vector2d& u, const ChairParams& p) {
  return wd::dynamicsF1(q, p) * u + wd::dynamicsF2(q, eta, p);
}

Eigen::Vector2d rollingResistanceTorque(const Eigen::Vector2d& eta, const ChairParams& p) {
  constexpr double kGravity = 9.81;
  constexpr double kSmoothingSpeed = 0.02;  // [m/s] rim speed where the sign is smoothed
  const double per_wheel =
      0.5 * p.rolling_resistance * (p.total_mass + 2.0 * p.wheel_mass) * kGravity * p.wheel_radius;
  return eta.unaryExpr(
      [&](double w) { return per_wheel * std::tanh(w * p.wheel_radius / kSmoothingSpeed); });
}

Vector5 configurationAtAxlePose(const wheelchair_core::Pose2D& pose, const ChairParams& p) {
  return wd::stateAtAxlePose(pose.x, pose.y, pose.yaw, p).head<5>();
}

}  // namespace wheelchair_controller
