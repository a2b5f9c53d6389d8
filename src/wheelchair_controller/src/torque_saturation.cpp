#include <wheelchair_controller/torque_saturation.h>

namespace wheelchair_controller {

SaturatedTorque saturateTorque(const Eigen::Vector2d& torque, double max_torque) {
  const double largest = torque.cwiseAbs().maxCoeff();
  if (largest <= max_torque) return {torque, 1.0};
  const double scale = max_torque / largest;
  return {torque * scale, scale};
}

}  // namespace wheelchair_controller
