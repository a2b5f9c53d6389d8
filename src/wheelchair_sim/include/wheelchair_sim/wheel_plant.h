// The torque input of the simulated chair, kept behind a small interface so that the ROS
// topic and the emulated CAN motor controller (motor_plant_adapter.h) drive the same simulator.
#pragma once

#include <Eigen/Core>

namespace wheelchair_sim {

/// What the motor side can sense: wheel angles psi and rates psi_dot, [right, left].
struct WheelReading {
  Eigen::Vector2d angle = Eigen::Vector2d::Zero();  ///< [rad]
  Eigen::Vector2d rate = Eigen::Vector2d::Zero();   ///< [rad/s]
};

/// Two driven wheels: set torques, read encoders.
class WheelPlant {
 public:
  virtual ~WheelPlant() = default;
  /// Torques held until the next call [N m], positive drives forward; non-finite -> 0.
  /// `brake` engages the parking brakes (commanded torques are then ignored).
  virtual void applyWheelTorques(double right, double left, bool brake) = 0;
  virtual WheelReading readWheels() const = 0;
};

}  // namespace wheelchair_sim
