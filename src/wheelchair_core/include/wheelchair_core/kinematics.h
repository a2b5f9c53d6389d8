// The chair's differential-drive kinematics, written once: the paper's eq. 10-11 (the body
// twist of the axle centre P from the wheel rates, q_dot = S(q) eta) and its inverse, and the
// exact integration of a constant twist. Used by the model, the base driver's encoder odometry,
// the simulator's odometry and the controller.
#pragma once

#include <wheelchair_core/pose2d.h>

namespace wheelchair_core {

/// The two numbers the kinematics need.
struct WheelBase {
  double wheel_radius = 0.0;  ///< r [m]
  double half_track = 0.0;    ///< b: half the distance between the drive wheels [m]
};

/// Forward speed of P and yaw rate.
struct BodyTwist {
  double v = 0.0;      ///< [m/s]
  double omega = 0.0;  ///< [rad/s]
};

/// Wheel rotation rates psi_dot (eta of eq. 11).
struct WheelRates {
  double right = 0.0;  ///< [rad/s]
  double left = 0.0;   ///< [rad/s]
};

/// Eq. 10-11: v = r (psi_r_dot + psi_l_dot) / 2, omega = r (psi_r_dot - psi_l_dot) / (2 b).
BodyTwist bodyTwist(const WheelRates& rates, const WheelBase& base);

/// The inverse of eq. 10-11: psi_r_dot = (v + b omega) / r, psi_l_dot = (v - b omega) / r.
WheelRates wheelRates(const BodyTwist& twist, const WheelBase& base);

/// Eq. 10-11 for distances rolled by each wheel (each with its own radius already applied):
/// the travel of P along its arc and the turn of the heading.
struct BodyMotion {
  double distance = 0.0;  ///< [m] along the arc
  double turn = 0.0;      ///< [rad]
};
BodyMotion bodyMotion(double travel_right, double travel_left, double half_track);

/// `pose` moved along an arc of length `motion.distance` while turning by `motion.turn`
/// (exact for a constant twist: the chord at the mid heading).
Pose2D integrateArc(const Pose2D& pose, const BodyMotion& motion);

}  // namespace wheelchair_core
