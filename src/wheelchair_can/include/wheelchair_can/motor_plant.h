// The motors seen from the emulated motor controller: whatever turns the wheels (the
// simulator's dynamics, or a trivial plant in tests) implements this interface.
#pragma once

#include <cstdint>

namespace wheelchair_can {

struct WheelAngles {
  double left = 0.0;   ///< [rad], unwrapped, increasing when the wheel rolls the chair forward
  double right = 0.0;  ///< [rad], unwrapped, increasing when the wheel rolls the chair forward
};

class MotorPlant {
 public:
  virtual ~MotorPlant() = default;
  /// Called by EmulatedMotorController::step() every step with the torques to apply until the
  /// next call [N m], positive = forward (REP-103), already saturated to the controller's limit.
  /// When `brake` is true the torques are 0 and the parking brakes hold the wheels.
  virtual void applyTorques(double left, double right, bool brake) = 0;
  /// Current wheel rotation angles; read every encoder period (100 Hz).
  virtual WheelAngles wheelAngles() const = 0;
  /// Hardware fault bits (protocol::FaultBit) the plant wants reported; 0 = healthy.
  virtual std::uint16_t hardwareFaults() const { return 0; }
};

}  // namespace wheelchair_can
