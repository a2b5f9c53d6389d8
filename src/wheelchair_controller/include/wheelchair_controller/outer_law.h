// The outer linear law acting on the linearized output dynamics y_ddot = v (eq. 21 makes the
// external part of eq. 20 a double integrator per axis).
#pragma once

#include <Eigen/Core>

namespace wheelchair_controller {

/// PD gains of v = y_ddot_ref + K_d (y_dot_ref - y_dot) + K_p (y_ref - y).
struct OuterGains {
  double kp = 0.0;  ///< [1/s^2]
  double kd = 0.0;  ///< [1/s]
};

/// Gains giving the error dynamics e_ddot + 2 zeta w_n e_dot + w_n^2 e = 0.
OuterGains gainsFromNaturalFrequency(double natural_frequency, double damping);

/// Reference of the output y = P_l: position, velocity and acceleration [m, m/s, m/s^2].
struct OutputReference {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  Eigen::Vector2d acceleration = Eigen::Vector2d::Zero();
};

/// Outer law: v = y_ddot_ref + sat(K_d (y_dot_ref - y_dot) + K_p (y_ref - y)). The feedback
/// part's magnitude is limited to max_feedback [m/s^2] (comfort while converging from a large
/// error; the saturated PD on a double integrator stays stable); linear below it.
Eigen::Vector2d outerLaw(const OutputReference& ref, const Eigen::Vector2d& y,
                         const Eigen::Vector2d& y_dot, const OuterGains& gains,
                         double max_feedback);

}  // namespace wheelchair_controller
