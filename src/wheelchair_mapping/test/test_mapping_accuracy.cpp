// Accuracy against ground truth: a map built from scans simulated (MRPT) in a known room from
// known poses. Of the cells the laser observed, >= 98 % are classified correctly at the 0.5
// threshold and walls are at most 2 cells thick.
#include <gtest/gtest.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/map_io.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "map_accuracy.h"
#include "synthetic_world.h"

namespace wheelchair_mapping {
namespace {

using test::Accuracy;
using test::compare;

Accuracy buildAndCompare(double noise_std) {
  mrpt::random::getRandomGenerator().randomize(1234);
  const OccupancyMap truth = test::syntheticRoom();
  const auto truth_grid = toMrptGrid(truth);
  BayesMapper mapper(MapperConfig{});
  double stamp = 0;
  for (const Pose2D& pose : test::loopTrajectory()) {
    const auto r =
        mapper.insert(test::simulateScan(truth_grid, pose, stamp += 0.2, noise_std), pose);
    EXPECT_TRUE(r.inserted) << r.reason;
  }
  GridThresholds half;  // the paper's classification: occupied iff P > 0.5
  half.occupied_thresh = 0.5;
  half.free_thresh = 0.5;
  if (const char* dump = std::getenv("MAPPING_ACCURACY_DUMP")) {
    saveMap(mapper.map(half), std::string(dump) + "_built.yaml");
    saveMap(truth, std::string(dump) + "_truth.yaml");
  }
  return compare(mapper.map(half), truth);
}

TEST(MappingAccuracy, NoiseFreeScansFromKnownPoses) {
  const Accuracy a = buildAndCompare(0.0);
  std::cout << "noise-free: " << a.correct << " / " << a.observed << " observed cells correct ("
            << 100 * a.fraction() << " %), thickest wall " << a.max_wall_run << " cells\n";
  RecordProperty("correct_percent", std::to_string(100 * a.fraction()));
  EXPECT_GT(a.observed, 20000) << "the 30 scans should observe most of the 80 m2 room";
  EXPECT_GE(a.fraction(), 0.98);
  EXPECT_LE(a.max_wall_run, 2);
}

TEST(MappingAccuracy, ScansWithOneCentimetreNoise) {
  const Accuracy a = buildAndCompare(0.01);
  std::cout << "sigma 1 cm: " << a.correct << " / " << a.observed << " observed cells correct ("
            << 100 * a.fraction() << " %), thickest wall " << a.max_wall_run << " cells\n";
  EXPECT_GE(a.fraction(), 0.98);
  EXPECT_LE(a.max_wall_run, 2);
}

}  // namespace
}  // namespace wheelchair_mapping
