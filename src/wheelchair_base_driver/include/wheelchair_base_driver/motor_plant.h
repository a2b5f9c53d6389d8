// The motors seen from the emulated motor controller: whatever turns the wheels (the
// simulator's dynamics, or a trivial plant in tests) implements this interface.
#pragma once

#include <cstdint>

namespace wheelchair_base_driver {

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

/// A trivial plant for tests and the driver's stand-alone fake mode: two independent wheels,
/// I dω/dt = τ - c ω, brake → ω = 0. Advanced explicitly with advance(dt).
class SimpleWheelPlant : public MotorPlant {
 public:
  SimpleWheelPlant(double inertia, double damping) : inertia_(inertia), damping_(damping) {}
  void applyTorques(double left, double right, bool brake) override;
  WheelAngles wheelAngles() const override { return angles_; }
  /// Integrates both wheels over `dt` seconds (semi-implicit Euler).
  void advance(double dt);
  double leftTorque() const { return left_; }
  double rightTorque() const { return right_; }
  bool braked() const { return brake_; }
  double leftRate() const { return rate_left_; }
  double rightRate() const { return rate_right_; }

 private:
  double inertia_, damping_;
  double left_ = 0.0, right_ = 0.0;
  bool brake_ = true;
  double rate_left_ = 0.0, rate_right_ = 0.0;
  WheelAngles angles_;
};

}  // namespace wheelchair_base_driver
