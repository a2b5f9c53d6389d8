// libFuzzer target for the decoder (wheelchair_can) and the driver's receive path (optional;
// the seeded gtests Fuzz.* of both packages are the ones in the suite). Each 13-byte chunk of the
// input is one frame: id (2, LE, 11 bits), flags (1: bit0 extended, bit1 remote, bit2 error),
// dlc (1, mod 9), data (8), time step (1, x 0.1 ms). Build and run from src/:
//   clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -Iwheelchair_base_driver/include
//   \
//     -Iwheelchair_can/include -Iwheelchair_core/include -Iwheelchair_description/include \
//     -I/usr/include/eigen3 wheelchair_base_driver/test/libfuzzer_receive_path.cpp \
//     wheelchair_base_driver/src/{base_driver_core,driver_config,encoder_odometry}.cpp \
//     wheelchair_can/src/*.cpp wheelchair_core/src/{config,kinematics}.cpp -lyaml-cpp \
//     -o /tmp/fuzz_rx && /tmp/fuzz_rx -runs=1000000
#include <wheelchair_base_driver/base_driver_core.h>
#include <wheelchair_can/fake_bus.h>

#include <cmath>
#include <cstdlib>

using namespace wheelchair_base_driver;
using wheelchair_can::CanFrame;
using wheelchair_can::FakeBus;
namespace protocol = wheelchair_can::protocol;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  auto bus = FakeBus::create();
  auto port = bus->connect("driver");
  auto monitor = bus->connect("monitor", 1u << 16);
  DriverConfig config;
  config.geometry = {0.17, 0.275, 4096, 40};
  config.max_torque = 50;
  config.max_speed = 1.5;
  BaseDriverCore driver(config, *port);
  double now = 0.001;
  std::uint64_t sequence = 0;
  driver.onCommand({3.0, -2.0, false, now, ++sequence, 1}, now);
  for (std::size_t i = 0; i + 13 <= size; i += 13) {
    const std::uint8_t* p = data + i;
    CanFrame f;
    f.id = (p[0] | (p[1] << 8)) & 0x7FF;
    f.extended = p[2] & 1;
    f.remote = p[2] & 2;
    f.error = p[2] & 4;
    f.dlc = p[3] % 9;
    for (int k = 0; k < 8; ++k) f.data[k] = p[4 + k];
    now += p[12] * 1e-4;
    protocol::Message m;
    protocol::decode(f, &m);
    driver.processFrame(f, now);
    if (p[12] & 1) driver.onCommand({3.0, -2.0, false, now, ++sequence, 1}, now);
    driver.spinOnce(now);
    const protocol::TorqueCommand& c = driver.lastCommand();
    // Only the commanded torques or a brake may ever be sent.
    const bool commanded =
        c.enable && !c.brake && std::abs(c.left - 3.0) < 0.006 && std::abs(c.right + 2.0) < 0.006;
    const bool braking = !c.enable && c.brake && c.left == 0.0 && c.right == 0.0;
    if (!(commanded || braking)) std::abort();
    if (driver.controllerFaults() != 0 && !braking) std::abort();
    if (!std::isfinite(driver.odometry().pose.x)) std::abort();
  }
  return 0;
}
