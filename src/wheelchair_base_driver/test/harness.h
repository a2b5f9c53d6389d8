// A driver and an emulated motor controller with a trivial plant on one fake bus, stepped
// with injected time. Shared by the driver and fuzz tests.
#pragma once

#include <wheelchair_base_driver/base_driver_core.h>
#include <wheelchair_can/emulated_motor_controller.h>
#include <wheelchair_can/fake_bus.h>
#include <wheelchair_can/simple_wheel_plant.h>

#include <cmath>
#include <functional>
#include <memory>

namespace wheelchair_base_driver::test {

using wheelchair_can::CanFrame;
using wheelchair_can::EmulatedControllerConfig;
using wheelchair_can::EmulatedMotorController;
using wheelchair_can::FakeBus;
using wheelchair_can::FakeBusEndpoint;
using wheelchair_can::SimpleWheelPlant;

inline DriverConfig testDriverConfig() {
  DriverConfig c;
  // Hand-built chair geometry (wheelchair_description's chair.yaml values are not needed here).
  c.geometry.wheel_radius = 0.17;
  c.geometry.half_track = 0.28;
  c.geometry.counts_per_rev = 4096;
  c.geometry.max_wheel_rate = 40;
  c.max_torque = 40;
  c.max_speed = 1.5;
  return c;
}

struct Harness {
  explicit Harness(const DriverConfig& config = testDriverConfig())
      : bus(FakeBus::create([this] { return now; })),
        driver_port(bus->connect("driver")),
        motor_port(bus->connect("motor")),
        monitor(bus->connect("monitor", 1u << 20)),
        plant(0.5, 0.2),
        driver(config, *driver_port),
        controller(EmulatedControllerConfig{}, *motor_port, plant) {}

  /// Advances time by `duration` in steps of `dt`, calling `each` (if any) before each step;
  /// while `supervised`, a permit every 20 ms (the supervisor's check rate), with `stop` and
  /// `speed_limit`.
  void run(double duration, double dt = 0.001, const std::function<void()>& each = {}) {
    const int steps = static_cast<int>(std::lround(duration / dt));
    for (int i = 0; i < steps; ++i) {
      now += dt;
      if (supervised && now >= next_permit - 1e-9) {
        permit();
        next_permit = now + 0.02;
      }
      if (each) each();
      controller.step(now);
      plant.advance(dt);
      driver.spinOnce(now, now);
    }
  }
  /// The supervisor's permit, now.
  void permit() {
    driver.onPermit(++permit_sequence, 1, now, stop, now, speed_limit);
    last_permit_time = now;
  }
  /// A command of the chair's controller, decided now (or `age` seconds ago).
  TorqueVerdict torque(double left, double right, bool brake = false, double age = 0.0) {
    return driver.onCommand({left, right, brake, now - age, ++command_sequence, 1}, now);
  }

  double now = 0.0;
  bool supervised = true, stop = false;
  double speed_limit = INFINITY;  ///< [m/s] the supervisor's, carried by its permits
  double next_permit = 0.0, last_permit_time = -1.0;
  std::uint64_t permit_sequence = 0, command_sequence = 0;
  std::shared_ptr<FakeBus> bus;
  std::shared_ptr<FakeBusEndpoint> driver_port, motor_port, monitor;
  SimpleWheelPlant plant;
  BaseDriverCore driver;
  EmulatedMotorController controller;
};

}  // namespace wheelchair_base_driver::test
