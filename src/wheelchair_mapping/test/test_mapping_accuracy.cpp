// Accuracy against ground truth: a map built from scans simulated (MRPT) in a known room from
// known poses. Of the cells the laser observed, >= 98 % are classified correctly at the 0.5
// threshold and walls are at most 2 cells thick.
#include <gtest/gtest.h>
#include <wheelchair_mapping/bayes_mapper.h>
#include <wheelchair_mapping/map_io.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "synthetic_world.h"

namespace wheelchair_mapping {
namespace {

struct Accuracy {
  int observed = 0;
  int correct = 0;
  int max_wall_run = 0;
  double fraction() const { return observed ? static_cast<double>(correct) / observed : 0.0; }
};

int occupiedRun(const OccupancyMap& m, int x, int y, int dx, int dy) {
  auto occupied = [&m](int cx, int cy) { return m.inBounds(cx, cy) && m.at(cx, cy) == kOccupied; };
  int n = 1;
  for (int k = 1; occupied(x + k * dx, y + k * dy); ++k) ++n;
  for (int k = 1; occupied(x - k * dx, y - k * dy); ++k) ++n;
  return n;
}

// True where two walls of the ground truth meet (corners, T-junctions) or within 5 cells of
// it: there a wall has no single thickness.
bool nearJunction(const OccupancyMap& truth, int tx, int ty) {
  for (int y = ty - 5; y <= ty + 5; ++y) {
    for (int x = tx - 5; x <= tx + 5; ++x) {
      if (truth.inBounds(x, y) && truth.at(x, y) == kOccupied &&
          std::min(occupiedRun(truth, x, y, 1, 0), occupiedRun(truth, x, y, 0, 1)) > 2) {
        return true;
      }
    }
  }
  return false;
}

// Wall thickness at an occupied cell away from junctions: the shorter of its horizontal and
// vertical runs of occupied cells (the run across the wall it stands in).
int maxWallThickness(const OccupancyMap& built, const OccupancyMap& truth) {
  int worst = 0;
  for (int y = 0; y < built.height; ++y) {
    for (int x = 0; x < built.width; ++x) {
      if (built.at(x, y) != kOccupied) continue;
      double wx, wy;
      int tx, ty;
      built.cellToWorld(x, y, wx, wy);
      if (truth.worldToCell(wx, wy, tx, ty) && nearJunction(truth, tx, ty)) continue;
      worst =
          std::max(worst, std::min(occupiedRun(built, x, y, 1, 0), occupiedRun(built, x, y, 0, 1)));
    }
  }
  return worst;
}

Accuracy compare(const OccupancyMap& built, const OccupancyMap& truth) {
  Accuracy a;
  for (int iy = 0; iy < built.height; ++iy) {
    for (int ix = 0; ix < built.width; ++ix) {
      const int8_t v = built.at(ix, iy);
      if (v == kUnknown) continue;
      double x, y;
      int tx, ty;
      built.cellToWorld(ix, iy, x, y);
      if (!truth.worldToCell(x, y, tx, ty)) {
        ++a.observed;  // observed outside the world: wrong by definition
        continue;
      }
      ++a.observed;
      a.correct += ((v == kOccupied) == (truth.at(tx, ty) == kOccupied)) ? 1 : 0;
    }
  }
  a.max_wall_run = maxWallThickness(built, truth);
  return a;
}

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
