#include <wheelchair_sim/wheel_torques.h>

#include <algorithm>
#include <cmath>

namespace wheelchair_sim {

namespace {
constexpr double kGravity = 9.80665;  // [m/s^2]
}  // namespace

double opposingTorque(double rate, double magnitude, double smoothing) {
  return -magnitude * std::tanh(rate / smoothing);
}

double rollingResistanceTorque(const wheelchair_description::ChairParams& chair) {
  const double mass = chair.total_mass + 2.0 * chair.wheel_mass;
  return 0.5 * chair.rolling_resistance * mass * kGravity * chair.wheel_radius;
}

Eigen::Vector2d limitedCommand(const Eigen::Vector2d& command, bool brake,
                               const wheelchair_description::ChairParams& chair,
                               const SimParams& params) {
  Eigen::Vector2d tau = Eigen::Vector2d::Zero();
  if (brake) return tau;
  for (int i = 0; i < 2; ++i) {
    tau(i) = std::isfinite(command(i)) ? command(i) : 0.0;
    if (params.torque_limit) {
      tau(i) = std::clamp(tau(i), -chair.max_wheel_torque, chair.max_wheel_torque);
    }
  }
  return tau;
}

Eigen::Vector2d wheelTorques(const Eigen::Vector2d& command, bool brake,
                             const Eigen::Vector2d& wheel_rates,
                             const wheelchair_description::ChairParams& chair,
                             const SimParams& params) {
  Eigen::Vector2d tau = limitedCommand(command, brake, chair, params);
  double resisting = params.rolling_resistance ? rollingResistanceTorque(chair) : 0.0;
  if (brake) resisting += params.brake_torque;
  if (resisting > 0.0) {
    for (int i = 0; i < 2; ++i) {
      tau(i) += opposingTorque(wheel_rates(i), resisting, params.resistance_smoothing);
    }
  }
  return tau;
}

}  // namespace wheelchair_sim
