// bench_insertion: time to insert one 361-beam, 180 deg scan (8 m range) at 5 cm, measured on
// scans MRPT simulates in the synthetic test room. Prints a JSON array (bench/mapping/run).
#include <wheelchair_mapping/bayes_mapper.h>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "synthetic_world.h"

int main() {
  using namespace wheelchair_mapping;
  const auto truth = toMrptGrid(test::syntheticRoom());
  const auto poses = test::loopTrajectory();
  std::vector<wheelchair_core::LaserScan2D> scans;
  for (size_t k = 0; k < poses.size(); ++k) scans.push_back(test::simulateScan(truth, poses[k], 0));
  BayesMapper mapper(MapperConfig{});
  // Wall time, and this thread's CPU time (insensitive to other processes on a busy machine).
  auto cpu_ms = [] {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
  };
  std::vector<double> ms, cpu;
  constexpr int kInsertions = 3000;
  for (int i = 0; i < kInsertions; ++i) {
    wheelchair_core::LaserScan2D scan = scans[i % scans.size()];
    scan.stamp = i;
    const double c0 = cpu_ms();
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = mapper.insert(scan, poses[i % poses.size()]).inserted;
    const auto t1 = std::chrono::steady_clock::now();
    cpu.push_back(cpu_ms() - c0);
    if (!ok) return 1;
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  auto mean = [](const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m += x / v.size();
    return m;
  };
  auto p99 = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[static_cast<size_t>(0.99 * (v.size() - 1))];
  };
  const char* row =
      "{\"case\": \"361 beams, 180 deg, 8 m, 5 cm\", \"method\": \"BayesMapper::insert\", "
      "\"metric\": \"%s\", \"value\": %.4f, \"unit\": \"ms\"}";
  std::printf("[");
  std::printf(row, "insert_mean_wall", mean(ms));
  std::printf(",\n ");
  std::printf(row, "insert_p99_wall", p99(ms));
  std::printf(",\n ");
  std::printf(row, "insert_mean_cpu", mean(cpu));
  std::printf(",\n ");
  std::printf(row, "insert_p99_cpu", p99(cpu));
  std::printf("]\n");
  return 0;
}
