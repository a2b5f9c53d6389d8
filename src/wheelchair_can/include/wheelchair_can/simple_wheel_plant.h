// Two independent wheels behind the MotorPlant interface (no chair dynamics).
#pragma once

#include <wheelchair_can/motor_plant.h>

namespace wheelchair_can {

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

}  // namespace wheelchair_can
