#include <wheelchair_can/simple_wheel_plant.h>

namespace wheelchair_can {

void SimpleWheelPlant::applyTorques(double left, double right, bool brake) {
  left_ = brake ? 0.0 : left;
  right_ = brake ? 0.0 : right;
  brake_ = brake;
}

void SimpleWheelPlant::advance(double dt) {
  const auto integrate = [this, dt](double torque, double& rate, double& angle) {
    rate = brake_ ? 0.0 : (rate + dt * torque / inertia_) / (1.0 + dt * damping_ / inertia_);
    angle += dt * rate;
  };
  integrate(left_, rate_left_, angles_.left);
  integrate(right_, rate_right_, angles_.right);
}

}  // namespace wheelchair_can
