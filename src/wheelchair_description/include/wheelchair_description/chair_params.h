// The physical parameters of the chair: one struct, filled from one YAML file
// (config/chair.yaml), read by the controller, the simulator and the base driver.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace wheelchair_description {

/// Symbols follow the paper (Figure 1, section 3). SI units (REP-103).
struct ChairParams {
  double total_mass = 0.0;          ///< M_T [kg], body + rider, without the two drive wheels
  double wheel_mass = 0.0;          ///< m_w [kg], one drive wheel with its motor rotor
  double wheel_inertia = 0.0;       ///< I_w [kg m^2], one drive wheel about its axle
  double wheel_inertia_diam = 0.0;  ///< I_m [kg m^2], one drive wheel about a diameter
  double body_inertia = 0.0;        ///< I_T [kg m^2], body + rider about the vertical through P_c
  double wheel_radius = 0.0;        ///< r [m]
  double half_track = 0.0;          ///< b [m], wheel centre to the symmetry axis
  double cm_offset = 0.0;           ///< d [m], from P_c (centre of mass) forward to P (axle centre)
  double lookahead = 0.0;           ///< L [m], from P forward to the controlled point P_l
  double max_wheel_torque = 0.0;    ///< [N m], per wheel, motor + gearbox limit
  double max_speed = 0.0;           ///< [m/s], forward speed limit of the power module
  double rolling_resistance = 0.0;  ///< c_rr [-], rolling-resistance coefficient of the tyres
  double width = 0.0;               ///< overall width [m]
  double length = 0.0;              ///< overall length [m]
  /// Footprint polygon in base_link (origin at P, x forward, y left), counter-clockwise [m].
  std::vector<Eigen::Vector2d> footprint;
  /// Laser scanner mount in base_link: x, y, z [m], yaw [rad].
  double laser_x = 0.0, laser_y = 0.0, laser_z = 0.0, laser_yaw = 0.0;

  /// Radius of the largest circle about P inside the footprint's width: width / 2.
  double inscribedRadius() const { return 0.5 * width; }
  /// Radius of the smallest circle about P enclosing the footprint.
  double circumscribedRadius() const;
};

/// Reads the chair's YAML file. Throws std::runtime_error naming the file and the
/// missing, non-finite or non-positive parameter.
ChairParams loadChairParams(const std::string& yaml_path);

/// Checks a parameter set; throws std::invalid_argument naming the first bad value.
void validate(const ChairParams& params);

/// Path of the chair file known at compile time (this package's install, else source dir):
/// for tests and tools. Nodelets resolve it at run time: chairParamsPathFromRos()
/// (package_paths.h), so an installed package works wherever it is installed.
std::string defaultChairParamsPath();

}  // namespace wheelchair_description
