// Benchmark of the controller on the ten flat paths (test_paths.h: flatTestPaths): time per
// control step and MSEre with the dynamic terms (the paper's controller) and without (kinematic
// baseline), on the model with a heavier rider, rolling resistance, encoders and pose noise.
// Prints a JSON array (bench/controller/run). Usage: controller_bench [chair.yaml]
#include <wheelchair_controller_test/closed_loop_simulation.h>
#include <wheelchair_controller_test/test_paths.h>
#include <wheelchair_description_testing/chair_file.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

using namespace wheelchair_controller;

namespace {

struct Row {
  std::string c, method, metric, unit;
  double value;
};

/// The test plant: heavier rider than the model assumes, rolling resistance, quantized
/// encoders, noisy pose (the Table 2 protocol of test_closed_loop.cpp).
PlantConfig realisticPlant(const ChairParams& model, unsigned seed) {
  PlantConfig plant;
  plant.chair = model;
  plant.chair.total_mass += 15.0;
  plant.chair.body_inertia *= 1.15;
  plant.pose_noise_xy = 0.005;
  plant.pose_noise_theta = 0.003;
  plant.seed = seed;
  return plant;
}

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / v.size();
}
double stddev(const std::vector<double>& v) {
  const double m = mean(v);
  double s = 0.0;
  for (double x : v) s += (x - m) * (x - m);
  return std::sqrt(s / (v.size() - 1));
}

}  // namespace

int main(int argc, char** argv) {
  const ChairParams model = wheelchair_description::loadChairParams(
      argc > 1 ? argv[1] : wheelchair_description::test::chairFile());
  std::vector<Row> rows;
  std::vector<double> step_times;
  for (const bool dynamic : {true, false}) {
    const std::string method = dynamic ? "feedback_linearization" : "kinematic_baseline";
    TrackerConfig config;
    config.dynamic_terms = dynamic;
    std::vector<double> mse, dev, acc, jerk;
    unsigned seed = 1;
    for (const NamedPath& p : flatTestPaths()) {
      const ClosedLoopResult r = simulateClosedLoop(p.poses, p.poses.front(), model, config,
                                                    realisticPlant(model, seed++));
      mse.push_back(r.mse_cm2);
      dev.push_back(r.body_deviation_max);
      acc.push_back(r.max_accel);
      jerk.push_back(r.max_jerk);
      rows.push_back({p.name, method, "mse_re", "cm^2", r.mse_cm2});
      rows.push_back({p.name, method, "goal_reached", "bool",
                      r.final_state == TrackerState::kGoalReached ? 1.0 : 0.0});
      if (dynamic)
        step_times.insert(step_times.end(), r.step_seconds.begin(), r.step_seconds.end());
    }
    rows.push_back({"10_flat_paths", method, "mse_re_mean", "cm^2", mean(mse)});
    rows.push_back({"10_flat_paths", method, "mse_re_std", "cm^2", stddev(mse)});
    rows.push_back({"10_flat_paths", method, "body_deviation_max", "m",
                    *std::max_element(dev.begin(), dev.end())});
    rows.push_back({"10_flat_paths", method, "rider_accel_max", "m/s^2",
                    *std::max_element(acc.begin(), acc.end())});
    rows.push_back({"10_flat_paths", method, "rider_jerk_max", "m/s^3",
                    *std::max_element(jerk.begin(), jerk.end())});
  }
  std::sort(step_times.begin(), step_times.end());
  rows.push_back(
      {"control_step", "feedback_linearization", "time_mean", "us", 1e6 * mean(step_times)});
  rows.push_back({"control_step", "feedback_linearization", "time_p99", "us",
                  1e6 * step_times[static_cast<size_t>(0.99 * (step_times.size() - 1))]});
  rows.push_back(
      {"control_step", "feedback_linearization", "time_max", "us", 1e6 * step_times.back()});
  // The reference of a new path is built off the control thread (the nodelet's worker).
  std::vector<double> build_times;
  for (const NamedPath& p : flatTestPaths()) {
    const auto t0 = std::chrono::steady_clock::now();
    const PreparedPath prepared = preparePath(p.poses, model, TrackerConfig{}, 0.0);
    build_times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (!prepared.rejection.empty())
      std::fprintf(stderr, "%s: %s\n", p.name.c_str(), prepared.rejection.c_str());
  }
  rows.push_back({"reference_build", "worker_thread", "time_mean", "ms", 1e3 * mean(build_times)});
  rows.push_back({"reference_build", "worker_thread", "time_max", "ms",
                  *std::max_element(build_times.begin(), build_times.end()) * 1e3});
  std::printf("[\n");
  for (size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    std::printf(
        "  {\"case\": \"%s\", \"method\": \"%s\", \"metric\": \"%s\", \"value\": %.6g, "
        "\"unit\": \"%s\"}%s\n",
        r.c.c_str(), r.method.c_str(), r.metric.c_str(), r.value, r.unit.c_str(),
        i + 1 < rows.size() ? "," : "");
  }
  std::printf("]\n");
  return 0;
}
