#include <wheelchair_base_driver/driver_config.h>
#include <wheelchair_can/protocol.h>
#include <wheelchair_core/config.h>

namespace wheelchair_base_driver {

std::string DriverConfig::validate() const {
  return wheelchair_core::ConfigChecks()
      .positive("wheel_radius", geometry.wheel_radius)
      .positive("half_track", geometry.half_track)
      .positive("counts_per_rev", geometry.counts_per_rev)
      .positive("max_wheel_rate", geometry.max_wheel_rate)
      .positive("max_torque", max_torque)
      .check(!(max_torque > wheelchair_can::protocol::kMaxEncodableTorque),
             "max_torque exceeds the protocol's 327.67 N m")
      .positive("command_period (1 / command_rate)", command_period)
      .positive("heartbeat_period", heartbeat_period)
      .positive("command_timeout", command_timeout)
      .positive("controller_timeout", controller_timeout)
      .positive("max_speed", max_speed)
      .positive("permit_timeout", permit_timeout)
      .positive("speed_limit_decel", speed_limit_decel)
      .positive("speed_limit_tolerance", speed_limit_tolerance)
      .positive("stop_window", stop_window)
      .positive("controller_wall_timeout", controller_wall_timeout)
      .positive("encoder_check_time", encoder_check_time)
      .positive("encoder_check_rate", encoder_check_rate)
      .positive("encoder_check_angle", encoder_check_angle)
      .positive("encoder_check_torque", encoder_check_torque)
      .positive("stall_torque", stall_torque)
      .positive("stall_time", stall_time)
      .result();
}

void readDriverConfig(wheelchair_core::ConfigReader& reader, DriverConfig& config) {
  reader.read("counts_per_rev", config.geometry.counts_per_rev);
  reader.read("max_wheel_rate", config.geometry.max_wheel_rate);
  reader.read("max_torque", config.max_torque);
  reader.read("max_speed", config.max_speed);
  double command_rate = 1.0 / config.command_period;
  reader.read("command_rate", command_rate);
  config.command_period = 1.0 / command_rate;
  reader.read("command_timeout", config.command_timeout);
  reader.read("controller_timeout", config.controller_timeout);
  reader.read("permit_timeout", config.permit_timeout);
  reader.read("speed_limit_decel", config.speed_limit_decel);
  reader.read("speed_limit_tolerance", config.speed_limit_tolerance);
  reader.read("stop_window", config.stop_window);
  reader.read("controller_wall_timeout", config.controller_wall_timeout);
  reader.read("encoder_check_time", config.encoder_check_time);
  reader.read("encoder_check_rate", config.encoder_check_rate);
  reader.read("encoder_check_angle", config.encoder_check_angle);
  reader.read("encoder_check_torque", config.encoder_check_torque);
  reader.read("stall_torque", config.stall_torque);
  reader.read("stall_time", config.stall_time);
}

}  // namespace wheelchair_base_driver
