// Accuracy against ground truth: a map built from scans simulated (MRPT) in a known room from
// known poses. Of the cells the laser observed, >= 98 % are classified correctly at the 0.5
// threshold and walls are at most 2 cells thick; no occupied cell lies farther off a wall than
// the range noise can put a return (ceil(5 sigma / res) cells), which a heading error breaks.
#include <gtest/gtest.h>
#include <wheelchair_core/map_io.h>
#include <wheelchair_mapping/bayes_mapper.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "map_accuracy.h"
#include "synthetic_world.h"

namespace wheelchair_mapping {
namespace {

using test::Accuracy;
using test::compare;

Accuracy buildAndCompare(double noise_std, double heading_error = 0.0) {
  mrpt::random::getRandomGenerator().randomize(1234);
  const wheelchair_core::OccupancyMap truth = test::syntheticRoom();
  const auto truth_grid = toMrptGrid(truth);
  BayesMapper mapper(MapperConfig{});
  double stamp = 0;
  for (const wheelchair_core::Pose2D& pose : test::loopTrajectory()) {
    const wheelchair_core::Pose2D believed{pose.x, pose.y, pose.yaw + heading_error};
    const auto r =
        mapper.insert(test::simulateScan(truth_grid, pose, stamp += 0.2, noise_std), believed);
    EXPECT_TRUE(r.inserted) << r.reason;
  }
  GridThresholds half;  // the paper's classification: occupied iff P > 0.5
  half.occupied_thresh = 0.5;
  half.free_thresh = 0.5;
  if (const char* dump = std::getenv("MAPPING_ACCURACY_DUMP")) {
    wheelchair_core::saveMap(mapper.map(half), std::string(dump) + "_built.yaml");
    wheelchair_core::saveMap(truth, std::string(dump) + "_truth.yaml");
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
  EXPECT_LE(a.max_spill, 1) << "5 sigma = 5 cm is one 5 cm cell in front of a wall";
}

// The spill bound of sim_mapping.test must catch a wrong pose: 0.02 rad moves a wall 4 m away
// by 8 cm, more than the noise's one cell.
TEST(MappingAccuracy, HeadingErrorSpillsBeyondTheNoiseBound) {
  const Accuracy a = buildAndCompare(0.01, 0.02);
  std::cout << "0.02 rad heading error: farthest off a wall " << a.max_spill << " cells\n";
  EXPECT_GT(a.max_spill, 1);
}

}  // namespace
}  // namespace wheelchair_mapping
