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
  return c;
}

struct Harness {
  Harness()
      : bus(FakeBus::create([this] { return now; })),
        driver_port(bus->connect("driver")),
        motor_port(bus->connect("motor")),
        monitor(bus->connect("monitor", 1u << 20)),
        plant(0.5, 0.2),
        driver(testDriverConfig(), *driver_port),
        controller(EmulatedControllerConfig{}, *motor_port, plant) {}

  /// Advances time by `duration` in steps of `dt`, calling `each` (if any) before each step.
  void run(double duration, double dt = 0.001, const std::function<void()>& each = {}) {
    const int steps = static_cast<int>(std::lround(duration / dt));
    for (int i = 0; i < steps; ++i) {
      now += dt;
      if (each) each();
      controller.step(now);
      plant.advance(dt);
      driver.spinOnce(now);
    }
  }
  void torque(double left, double right, bool brake = false) {
    driver.onTorqueMessage(left, right, brake, 0.0, now);
  }

  double now = 0.0;
  std::shared_ptr<FakeBus> bus;
  std::shared_ptr<FakeBusEndpoint> driver_port, motor_port, monitor;
  SimpleWheelPlant plant;
  BaseDriverCore driver;
  EmulatedMotorController controller;
};

}  // namespace wheelchair_base_driver::test
