// bench/sim: simulated seconds per wall-clock second of the simulator core (dynamics at
// physics_rate, odometry, laser at laser_rate), on the given worlds. Prints a JSON array.
// usage: bench_sim SIM_SECONDS WORLD.yaml [WORLD.yaml ...]
#include <wheelchair_description/chair_file.h>
#include <wheelchair_description/model.h>
#include <wheelchair_sim/simulated_chair.h>
#include <wheelchair_sim/world_loader.h>

#include <ros/package.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace {

using wheelchair_sim::SimulatedChair;

/// A pose near the middle of the world where the chair can spin with 0.3 m to spare,
/// searched outward on a 0.25 m grid.
bool findFreePose(SimulatedChair& sim, const mrpt::maps::COccupancyGridMap2D& g) {
  const double cx = 0.5 * (g.getXMin() + g.getXMax()), cy = 0.5 * (g.getYMin() + g.getYMax());
  auto roomy = [&](double x, double y) {
    for (double a = 0.0; a < 2 * M_PI; a += M_PI / 8) {
      for (double dx : {-0.3, 0.0, 0.3}) {
        for (double dy : {-0.3, 0.0, 0.3}) {
          if (sim.simulator().collides({x + dx, y + dy, a})) return false;
        }
      }
    }
    return true;
  };
  for (double r = 0.0; r < 0.5 * (g.getXMax() - g.getXMin()); r += 0.25) {
    for (double a = 0.0; a < 2 * M_PI; a += 0.1) {
      const double x = cx + r * std::cos(a), y = cy + r * std::sin(a);
      if (roomy(x, y)) return sim.reset({x, y, 0.0});
    }
  }
  return false;
}

/// Simulated seconds per wall second while the chair spins in place at 0.6 rad/s (a wheel
/// speed loop as a motor controller would run it), so the laser sweeps the whole world.
/// Negative if the chair collided (the measurement would be meaningless).
double realTimeFactor(SimulatedChair& sim, double seconds, double step) {
  const Eigen::Vector2d target =
      wheelchair_description::wheelSpeeds(0.0, 0.6, sim.simulator().chair());
  const auto start = std::chrono::steady_clock::now();
  for (double t = 0.0; t < seconds; t += step) {
    const Eigen::Vector2d tau = 20.0 * (target - sim.simulator().readWheels().rate);
    sim.simulator().applyWheelTorques(tau(0), tau(1), false);
    sim.advance(step);
  }
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return sim.simulator().collided() ? -1.0 : seconds / wall;
}

std::string stem(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const std::string name = path.substr(slash == std::string::npos ? 0 : slash + 1);
  return name.substr(0, name.find('.'));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: bench_sim SIM_SECONDS WORLD.yaml [WORLD.yaml ...]\n";
    return 2;
  }
  const double seconds = std::stod(argv[1]);
  // The chair and sim.yaml of the packages found at run time (as the simulator node does).
  const auto chair =
      wheelchair_description::loadChairParams(wheelchair_description::defaultChairFile());
  const auto params =
      wheelchair_sim::loadSimParams(ros::package::getPath("wheelchair_sim") + "/config/sim.yaml");
  bool first = true;
  std::printf("[");
  for (int i = 2; i < argc; ++i) {
    const auto world = wheelchair_sim::loadWorld(argv[i]);
    for (bool laser : {true, false}) {
      auto p = params;
      p.laser_enabled = laser;
      SimulatedChair sim(chair, p, world);
      if (!findFreePose(sim, *world)) {
        std::cerr << "no free pose in " << argv[i] << "\n";
        return 1;
      }
      const double factor = realTimeFactor(sim, seconds, 0.005);
      if (factor < 0.0) {
        std::cerr << "the chair collided in " << argv[i] << ": no figure\n";
        return 1;
      }
      std::printf(
          "%s\n {\"case\": \"%s\", \"method\": \"%s\", \"metric\": \"real_time_factor\", "
          "\"value\": %.1f, \"unit\": \"sim s / wall s\"}",
          first ? "" : ",", stem(argv[i]).c_str(),
          laser ? "rk4_1kHz+laser_10Hz_361" : "rk4_1kHz_no_laser", factor);
      first = false;
    }
  }
  std::printf("\n]\n");
  return 0;
}
