// bench_insertion: time to insert one 361-beam, 180 deg scan (8 m range) at 5 cm, measured on
// scans MRPT simulates in the synthetic test room. Prints a JSON array (bench/mapping/run).
#include <wheelchair_mapping/bayes_mapper.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "synthetic_world.h"

int main() {
  using namespace wheelchair_mapping;
  const auto truth = toMrptGrid(test::syntheticRoom());
  const auto poses = test::loopTrajectory();
  std::vector<LaserScan2D> scans;
  for (size_t k = 0; k < poses.size(); ++k) scans.push_back(test::simulateScan(truth, poses[k], 0));
  BayesMapper mapper(MapperConfig{});
  std::vector<double> ms;
  constexpr int kInsertions = 3000;
  for (int i = 0; i < kInsertions; ++i) {
    LaserScan2D scan = scans[i % scans.size()];
    scan.stamp = i;
    const auto t0 = std::chrono::steady_clock::now();
    const bool ok = mapper.insert(scan, poses[i % poses.size()]).inserted;
    const auto t1 = std::chrono::steady_clock::now();
    if (!ok) return 1;
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  double mean = 0;
  for (double v : ms) mean += v / ms.size();
  std::sort(ms.begin(), ms.end());
  const double p99 = ms[static_cast<size_t>(0.99 * (ms.size() - 1))];
  std::printf(
      "[{\"case\": \"361 beams, 180 deg, 8 m, 5 cm\", \"method\": \"BayesMapper::insert\", "
      "\"metric\": \"insert_mean\", \"value\": %.4f, \"unit\": \"ms\"},\n"
      " {\"case\": \"361 beams, 180 deg, 8 m, 5 cm\", \"method\": \"BayesMapper::insert\", "
      "\"metric\": \"insert_p99\", \"value\": %.4f, \"unit\": \"ms\"}]\n",
      mean, p99);
  return 0;
}
