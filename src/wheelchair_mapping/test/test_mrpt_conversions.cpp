#include <gtest/gtest.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <wheelchair_mapping/mrpt_conversions.h>

#include <random>

namespace wheelchair_mapping {
namespace {

wheelchair_core::OccupancyMap roomWithWallAt(double wall_x) {
  wheelchair_core::OccupancyMap map;
  map.resolution = 0.05;
  map.origin_x = -2.013;  // deliberately not a multiple of the resolution
  map.origin_y = -1.987;
  map.width = 120;
  map.height = 80;
  map.data.assign(static_cast<size_t>(map.width) * map.height, wheelchair_core::kFree);
  for (int iy = 0; iy < map.height; ++iy) {
    for (int ix = 0; ix < map.width; ++ix) {
      double x, y;
      map.cellToWorld(ix, iy, x, y);
      if (std::abs(x - wall_x) < map.resolution / 2) map.at(ix, iy) = wheelchair_core::kOccupied;
    }
  }
  map.at(0, 0) = wheelchair_core::kUnknown;
  return map;
}

TEST(MrptConversions, KeepsGeometryAndCellsExactly) {
  const wheelchair_core::OccupancyMap map = roomWithWallAt(1.5);
  const auto grid = toMrptGrid(map);
  EXPECT_EQ(grid.getSizeX(), 120u);
  EXPECT_EQ(grid.getSizeY(), 80u);
  EXPECT_NEAR(grid.getXMin(), map.origin_x, 1e-6);
  EXPECT_NEAR(grid.getYMin(), map.origin_y, 1e-6);
  // The same world point falls in the same cell in both.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> ux(-2.0, 3.9), uy(-1.9, 1.9);
  for (int k = 0; k < 200; ++k) {
    const double x = ux(rng), y = uy(rng);
    int ix, iy;
    ASSERT_TRUE(map.worldToCell(x, y, ix, iy));
    EXPECT_EQ(grid.x2idx(x), ix);
    EXPECT_EQ(grid.y2idx(y), iy);
  }
  // MRPT cells hold P(free).
  int wall_ix, wall_iy;
  ASSERT_TRUE(map.worldToCell(1.5, 0.0, wall_ix, wall_iy));
  EXPECT_LT(grid.getCell(wall_ix, wall_iy), 0.01f);
  EXPECT_GT(grid.getCell(5, 40), 0.99f);
  EXPECT_EQ(grid.getCell(0, 0), 0.5f);
  const wheelchair_core::OccupancyMap back = fromMrptGrid(grid);
  EXPECT_EQ(back.width, map.width);
  EXPECT_EQ(back.height, map.height);
  EXPECT_NEAR(back.origin_x, map.origin_x, 1e-6);
  EXPECT_NEAR(back.resolution, map.resolution, 1e-7);
  EXPECT_EQ(back.data, map.data);
}

TEST(MrptConversions, SimulatedLaserSeesTheWallWhereTheMapHasIt) {
  const double wall_x = 1.5;
  const auto grid = toMrptGrid(roomWithWallAt(wall_x));
  mrpt::obs::CObservation2DRangeScan scan;
  scan.aperture = static_cast<float>(M_PI);
  scan.maxRange = 8.0f;
  grid.laserScanSimulator(scan, mrpt::poses::CPose2D(0.0, 0.0, 0.0), 0.5f, 181);
  ASSERT_TRUE(scan.getScanRangeValidity(90));
  // The wall's near face is at wall_x - resolution / 2 from the sensor at x = 0.
  EXPECT_NEAR(scan.getScanRange(90), wall_x - 0.025, 0.05);
}

TEST(MrptConversions, GradedValuesAndThresholds) {
  wheelchair_core::OccupancyMap map;
  map.width = 4;
  map.height = 1;
  map.data = {10, 40, 80, wheelchair_core::kUnknown};
  const auto grid = toMrptGrid(map);
  GridThresholds graded;
  graded.trinary = false;
  const wheelchair_core::OccupancyMap back = fromMrptGrid(grid, graded);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(back.data[i], map.data[i], 1) << i;
  EXPECT_EQ(back.data[3], wheelchair_core::kUnknown);
  const wheelchair_core::OccupancyMap tri = fromMrptGrid(grid);  // 0.196 / 0.65
  EXPECT_EQ(tri.data, (std::vector<int8_t>{wheelchair_core::kFree, wheelchair_core::kUnknown,
                                           wheelchair_core::kOccupied, wheelchair_core::kUnknown}));
  map.origin_yaw = 0.1;
  EXPECT_THROW(toMrptGrid(map), std::invalid_argument);
}

}  // namespace
}  // namespace wheelchair_mapping
