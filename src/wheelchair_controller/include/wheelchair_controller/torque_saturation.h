// Wheel torque limits that keep the direction of the commanded torque vector.
#pragma once

#include <Eigen/Core>

namespace wheelchair_controller {

struct SaturatedTorque {
  Eigen::Vector2d torque;  ///< [tau_r, tau_l] within the limit [N m]
  double scale = 1.0;      ///< factor applied to both wheels (1 = unsaturated)
};

/// Scales both wheel torques by the same factor so that neither exceeds max_torque: the ratio
/// tau_r / tau_l (turning versus driving) is kept, unlike clipping one wheel, which would turn
/// the chair. The scale feeds the reference governor (anti-windup, see PathTracker).
SaturatedTorque saturateTorque(const Eigen::Vector2d& torque, double max_torque);

}  // namespace wheelchair_controller
