// The physical parameters of the chair: one struct, filled from one YAML file
// (config/chair.yaml), read by the controller, the simulator and the base driver. One
// parameter pattern (wheelchair_core/config.h): readChairParams names every key (all of them
// required: a chair file is complete), validate() says what is wrong, an unknown key is refused.
#pragma once

#include <wheelchair_core/kinematics.h>
#include <wheelchair_core/polygon.h>

#include <string>

namespace wheelchair_core {
class ConfigReader;
}

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
  wheelchair_core::Polygon footprint;
  /// Laser scanner mount in base_link: x, y, z [m], yaw [rad] (keys laser/x ... laser/yaw).
  double laser_x = 0.0, laser_y = 0.0, laser_z = 0.0, laser_yaw = 0.0;
  /// Rear laser scanner mount in base_link, looking behind the chair (keys rear_laser/x ...
  /// rear_laser/yaw): what guards reverse motion.
  double rear_laser_x = 0.0, rear_laser_y = 0.0, rear_laser_z = 0.0, rear_laser_yaw = 0.0;
  /// The controlled stop the safety supervisor's protective field plans for (keys
  /// protective_field/reaction_time ... /margin): the field's stop zone is the chair's front
  /// (footprint) + the distance of this stop + margin (wheelchair_safety/protective_field.h).
  /// (A file must state them; these initial values only keep hand-built chairs of tests valid.)
  struct StopFigures {
    double reaction_time = 0.3;  ///< [s] from a return in the field to the brake's onset
    double brake_decel = 0.5;    ///< [m/s^2] the controlled stop's deceleration
    double brake_jerk = 1.0;     ///< [m/s^3] its ramp
    double drive_accel = 0.35;   ///< [m/s^2] worst case still accelerating meanwhile
    double margin = 0.2;         ///< [m] beyond the stop
  } stop;

  /// Radius of the largest circle about P inside the footprint's width: width / 2.
  double inscribedRadius() const { return 0.5 * width; }
  /// Radius of the smallest circle about P enclosing the footprint.
  double circumscribedRadius() const { return wheelchair_core::circumscribedRadius(footprint); }
  /// r and b, what the kinematics (eq. 10-11) need.
  wheelchair_core::WheelBase wheelBase() const { return {wheel_radius, half_track}; }

  /// "" if the chair is physically meaningful, else every problem, each naming its parameter
  /// in quotes ("chair parameter 'half_track' must be finite and positive (got -0.2)").
  std::string validate() const;
};

/// Every key of a chair file, each required: the scalars by their member names, footprint
/// (a list of [x, y]), laser/x, laser/y, laser/z, laser/yaw, rear_laser/x ... rear_laser/yaw and
/// protective_field/{reaction_time, brake_decel, brake_jerk, drive_accel, margin}.
void readChairParams(wheelchair_core::ConfigReader& reader, ChairParams& params);

/// Reads and validates a chair file. Throws wheelchair_core::ConfigError naming the file and
/// the unreadable file, the missing, unknown, non-numeric or invalid parameter.
ChairParams loadChairParams(const std::string& yaml_path);

}  // namespace wheelchair_description
