#include <wheelchair_controller/torque_saturation.h>

namespace wheelchair_controller {

SaturatedTorque saturateTorque(const Eigen::Vector2d& torque, double max_torque) {
  const double largest = torque.cwiseAbs().maxCoeff();
  if (largest <= max_torque) return {torque, 1.0};
  const double scale = max_torque / largest;
  // The clamp only removes the rounding of the product (e.g. 50.000000000000007): the base
  // driver rejects anything beyond max_torque, so the saturated wheel must be exactly at it.
  const Eigen::Vector2d scaled = (torque * scale).cwiseMax(-max_torque).cwiseMin(max_torque);
  return {scaled, scale};
}

}  // namespace wheelchair_controller
