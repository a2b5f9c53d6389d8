// What the driver core needs to know: the chair's wheels and encoders, the torque limit, the
// command and heartbeat rates and the two watchdogs. One parameter pattern
// (wheelchair_core/config.h): defaults here, validate(), and the keys in readDriverConfig.
#pragma once

#include <wheelchair_base_driver/encoder_odometry.h>

#include <string>

namespace wheelchair_core {
class ConfigReader;
}

namespace wheelchair_base_driver {

struct DriverConfig {
  WheelGeometry geometry;
  /// [N m] per wheel; larger |torque| is rejected. The nodelet starts from the chair file's
  /// max_wheel_torque.
  double max_torque = 0.0;
  double command_period = 0.01;     ///< torque frames are repeated at this period (100 Hz)
  double heartbeat_period = 0.05;   ///< driver heartbeat period (20 Hz)
  double command_timeout = 0.1;     ///< torque message watchdog [s]
  double controller_timeout = 0.2;  ///< MC heartbeat watchdog [s]

  /// "" if usable, else every problem, each naming its value.
  std::string validate() const;
};

/// Keys: counts_per_rev, max_wheel_rate, max_torque, command_rate [Hz] (1 / command_period),
/// command_timeout, controller_timeout. The wheel radius and half track are not keys: they are
/// the chair file's.
void readDriverConfig(wheelchair_core::ConfigReader& reader, DriverConfig& config);

}  // namespace wheelchair_base_driver
