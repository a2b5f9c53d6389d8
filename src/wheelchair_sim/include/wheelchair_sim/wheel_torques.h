// The torque that actually reaches each wheel: the command after the motor limit, plus the
// resisting torques (rolling resistance, parking brake). ROS-free, Eigen only.
#pragma once

#include <wheelchair_description/chair_params.h>
#include <wheelchair_sim/sim_params.h>

#include <Eigen/Core>

namespace wheelchair_sim {

/// A torque of `magnitude` opposing a wheel turning at `rate` [rad/s]:
/// -magnitude tanh(rate / smoothing). Smooth through zero, so a coasting chair comes to
/// rest without chattering, and exactly zero at rest.
double opposingTorque(double rate, double magnitude, double smoothing);

/// Rolling resistance of one drive wheel: c_rr m g r / 2, m the whole chair incl. wheels
/// (the resisting force c_rr m g shared by the two drive wheels) [N m].
double rollingResistanceTorque(const wheelchair_description::ChairParams& chair);

/// Commanded torques [right, left] after the motor limit (if on) and with non-finite
/// values replaced by zero.
Eigen::Vector2d limitedCommand(const Eigen::Vector2d& command, bool brake,
                               const wheelchair_description::ChairParams& chair,
                               const SimParams& params);

/// Total wheel torque for the current wheel rates: limited command + resistances.
Eigen::Vector2d wheelTorques(const Eigen::Vector2d& command, bool brake,
                             const Eigen::Vector2d& wheel_rates,
                             const wheelchair_description::ChairParams& chair,
                             const SimParams& params);

}  // namespace wheelchair_sim
