// Input-output feedback linearization of the paper's dynamic model (section 3.3, eqs. 18-21).
// Output y = P_l, the virtual point d+L ahead of the centre of mass P_c (L ahead of the axle P).
// Each function also takes the output point's signed offset ell from the axle (ell = L: the
// paper's P_l; ell = -L_r: the point P_r behind the axle that reverse tracking uses, because
// the zero dynamics are stable only with the output point on the side the chair moves towards:
// README, "Reverse").
#pragma once

#include <wheelchair_core/pose2d.h>
#include <wheelchair_description/chair_params.h>
#include <wheelchair_description/model.h>

#include <Eigen/Core>

namespace wheelchair_controller {

using wheelchair_description::ChairParams;
using wheelchair_description::Vector5;
using Matrix25 = Eigen::Matrix<double, 2, 5>;

/// Eq. 18: y = h(q) = P_c + (d+L)(cos theta, sin theta), the virtual point P_l. With ell:
/// P_c + (d+ell)(cos theta, sin theta) = P + ell (cos theta, sin theta).
Eigen::Vector2d outputPoint(const Vector5& q, const ChairParams& p);
Eigen::Vector2d outputPoint(const Vector5& q, const ChairParams& p, double ell);

/// Jacobian J_h = dh/dq of eq. 18 (2x5).
Matrix25 outputJacobian(const Vector5& q, const ChairParams& p);
Matrix25 outputJacobian(const Vector5& q, const ChairParams& p, double ell);

/// Eq. 19: decoupling matrix Phi(q) = J_h(q) S(q). det Phi = -2 b L c^2, c = r/(2b):
/// invertible iff L != 0, i.e. iff P_l is off the wheel axle (-2 b ell c^2 with ell).
Eigen::Matrix2d decouplingMatrix(const Vector5& q, const ChairParams& p);
Eigen::Matrix2d decouplingMatrix(const Vector5& q, const ChairParams& p, double ell);

/// Time derivative of Phi along the motion q_dot = S(q) eta: J_h_dot S + J_h S_dot.
Eigen::Matrix2d decouplingMatrixDot(const Vector5& q, const Eigen::Vector2d& eta,
                                    const ChairParams& p);
Eigen::Matrix2d decouplingMatrixDot(const Vector5& q, const Eigen::Vector2d& eta,
                                    const ChairParams& p, double ell);

/// Eq. 19 (first line): y_dot = Phi(q) eta.
Eigen::Vector2d outputVelocity(const Vector5& q, const Eigen::Vector2d& eta, const ChairParams& p);
Eigen::Vector2d outputVelocity(const Vector5& q, const Eigen::Vector2d& eta, const ChairParams& p,
                               double ell);

/// Eq. 21 (derived from eq. 19 with eta_dot = u): u = Phi^{-1} (v - Phi_dot eta), so that
/// y_ddot = v. (The paper's summary line "u = Phi_dot^{-1}(v - Phi eta)" is garbled.)
Eigen::Vector2d linearizingInput(const Vector5& q, const Eigen::Vector2d& eta,
                                 const Eigen::Vector2d& v, const ChairParams& p);
Eigen::Vector2d linearizingInput(const Vector5& q, const Eigen::Vector2d& eta,
                                 const Eigen::Vector2d& v, const ChairParams& p, double ell);

/// The zero dynamics of the output y = P + ell h(theta) (README, "Reverse"): with y held on a
/// reference moving with velocity y_dot_ref, the heading left to itself obeys
/// theta_dot = (1/ell) n(theta) . y_dot_ref (from y_dot = v h + ell theta_dot n). Returns
/// theta_dot.
double zeroDynamicsHeadingRate(double theta, const Eigen::Vector2d& y_dot_ref, double ell);

/// Section 3.3 nonlinear feedback: tau = f1(q) u + f2(q, eta), which turns eq. 14 into
/// eta_dot = u.
Eigen::Vector2d computedTorque(const Vector5& q, const Eigen::Vector2d& eta,
                               const Eigen::Vector2d& u, const ChairParams& p);

/// Torque [N m] per wheel that balances rolling resistance (c_rr (M_T + 2 m_w) g r / 2 each,
/// opposing the wheel's rotation; smoothed around zero speed). Not in the paper's model: a
/// feed-forward for the real chair (and the test plant).
Eigen::Vector2d rollingResistanceTorque(const Eigen::Vector2d& eta, const ChairParams& p);

/// Configuration q of the model for an axle pose (x, y, theta) of base_link (P).
Vector5 configurationAtAxlePose(const wheelchair_core::Pose2D& pose, const ChairParams& p);

}  // namespace wheelchair_controller
