#include <wheelchair_controller/outer_law.h>

namespace wheelchair_controller {

OuterGains gainsFromNaturalFrequency(double natural_frequency, double damping) {
  return {natural_frequency * natural_frequency, 2.0 * damping * natural_frequency};
}

Eigen::Vector2d outerLaw(const OutputReference& ref, const Eigen::Vector2d& y,
                         const Eigen::Vector2d& y_dot, const OuterGains& gains,
                         double max_feedback) {
  Eigen::Vector2d feedback = gains.kd * (ref.velocity - y_dot) + gains.kp * (ref.position - y);
  const double norm = feedback.norm();
  if (norm > max_feedback) feedback *= max_feedback / norm;
  return ref.acceleration + feedback;
}

}  // namespace wheelchair_controller
