// Lets wheelchair_can's emulated CAN motor controller drive the simulator: its MotorPlant
// interface (left/right) mapped onto the simulator's WheelPlant (right/left).
#pragma once

#include <wheelchair_can/motor_plant.h>
#include <wheelchair_sim/wheel_plant.h>

namespace wheelchair_sim {

class SimulatorMotorPlant : public wheelchair_can::MotorPlant {
 public:
  explicit SimulatorMotorPlant(WheelPlant& wheels) : wheels_(wheels) {}

  void applyTorques(double left, double right, bool brake) override {
    wheels_.applyWheelTorques(right, left, brake);
  }

  wheelchair_can::WheelAngles wheelAngles() const override {
    const WheelReading r = wheels_.readWheels();
    wheelchair_can::WheelAngles angles;
    angles.left = r.angle(1);
    angles.right = r.angle(0);
    return angles;
  }

 private:
  WheelPlant& wheels_;
};

}  // namespace wheelchair_sim
