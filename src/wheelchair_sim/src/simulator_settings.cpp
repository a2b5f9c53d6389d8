#include <wheelchair_core/config.h>
#include <wheelchair_sim/simulator_settings.h>

namespace wheelchair_sim {

std::string SimulatorSettings::validate() const {
  const std::string sim_problem = sim.validate();
  const std::string motor_problem = motor_controller.validate();
  const auto port = [](int p) { return p >= 0 && p <= 65535; };
  return wheelchair_core::ConfigChecks()
      .check(sim_problem.empty(), sim_problem)
      .check(!world.empty(), "world (a map_server YAML) must be set")
      .positive("step", step)
      .nonNegative("speed", speed)
      .positive("torque_timeout", torque_timeout)
      .check(initial.isFinite(), "initial_x, initial_y, initial_yaw must be finite")
      .check(motor_bus.empty() || motor_bus == "udp" || motor_bus == "fake",
             "unknown motor_bus '" + motor_bus + "' (\"\" = /wheel_torques, \"udp\", \"fake\")")
      .check(port(udp_local_port) && port(udp_remote_port), "UDP ports must be in 0..65535")
      .check(!fake_bus.empty(), "fake_bus must not be empty")
      .check(motor_problem.empty(), "motor controller: " + motor_problem)
      .check(!map_frame.empty() && !odom_frame.empty() && !base_frame.empty() &&
                 !laser_frame.empty() && !rear_laser_frame.empty(),
             "frames must not be empty")
      .result();
}

void readSimulatorSettings(wheelchair_core::ConfigReader& reader, SimulatorSettings& s) {
  reader.require("world", s.world);
  reader.renamed("chair_config", "chair_file");
  reader.read("chair_file", s.chair_file);
  reader.read("sim_config", s.sim_config);
  readSimParams(reader, s.sim);
  reader.read("speed", s.speed);
  reader.read("step", s.step);
  reader.read("torque_timeout", s.torque_timeout);
  reader.read("initial_x", s.initial.x);
  reader.read("initial_y", s.initial.y);
  reader.read("initial_yaw", s.initial.yaw);
  reader.read("publish_odometry", s.publish_odometry);
  reader.read("publish_laser_tf", s.publish_laser_tf);
  reader.read("motor_bus", s.motor_bus);
  reader.read("udp_local_port", s.udp_local_port);
  reader.read("udp_remote_port", s.udp_remote_port);
  reader.read("fake_bus", s.fake_bus);
  wheelchair_can::readEmulatedControllerConfig(reader, s.motor_controller);
  reader.read("map_frame", s.map_frame);
  reader.read("odom_frame", s.odom_frame);
  reader.read("base_frame", s.base_frame);
  reader.read("laser_frame", s.laser_frame);
  reader.read("rear_laser_frame", s.rear_laser_frame);
  reader.allow("obstacles");
}

}  // namespace wheelchair_sim
