// The C-space: dilation radius, unknown cells, conductance of the clearance band.
#include <wheelchair_planner/config_space.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace wheelchair_planner;
using wheelchair_core::OccupancyMap;

namespace {

OccupancyMap freeMap(int w, int h, double res) {
  OccupancyMap m;
  m.width = w;
  m.height = h;
  m.resolution = res;
  m.data.assign(static_cast<size_t>(w) * h, wheelchair_core::kFree);
  return m;
}

}  // namespace

TEST(ConfigSpace, DilatesAnObstacleByRadiusPlusMargin) {
  OccupancyMap m = freeMap(81, 81, 0.05);
  m.at(40, 40) = wheelchair_core::kOccupied;
  ConfigSpaceParams p;
  p.inscribed_radius = 0.31;
  p.min_clearance = 0.05;
  const ConfigSpace cs(m, p);
  for (int iy = 10; iy < 71; ++iy) {
    for (int ix = 10; ix < 71; ++ix) {
      // Distance from this cell's centre to the obstacle cell's nearest edge, analytically.
      const double centre = std::hypot(ix - 40, iy - 40) * 0.05;
      const double gap = centre - 0.025;
      if (std::abs(gap - 0.36) < 0.002 || (ix == 40 && iy == 40)) continue;  // on the boundary
      EXPECT_EQ(cs.isFree(ix, iy), gap > 0.36) << ix << "," << iy;
    }
  }
  EXPECT_NEAR(cs.clearanceAt(40 * 0.05 + 0.025 + 1.0, 40 * 0.05 + 0.025), 1.0 - 0.025 - 0.31, 1e-3);
}

TEST(ConfigSpace, UnknownIsObstacleByDefault) {
  OccupancyMap m = freeMap(60, 60, 0.05);
  m.at(30, 30) = wheelchair_core::kUnknown;
  ConfigSpaceParams p;
  EXPECT_FALSE(ConfigSpace(m, p).isFree(30, 30 + 5));
  p.unknown_is_obstacle = false;
  EXPECT_TRUE(ConfigSpace(m, p).isFree(30, 30 + 5));
}

TEST(ConfigSpace, MapBorderIsAnObstacle) {
  const ConfigSpace cs(freeMap(40, 40, 0.05), ConfigSpaceParams());
  EXPECT_FALSE(cs.isFree(3, 20));  // 0.15 m from the edge < 0.36 m
  EXPECT_TRUE(cs.isFree(20, 20));
}

TEST(ConfigSpace, ConductanceRampsAcrossTheClearanceBand) {
  OccupancyMap m = freeMap(200, 40, 0.05);
  for (int ix = 0; ix < 200; ++ix) m.at(ix, 0) = wheelchair_core::kOccupied;
  ConfigSpaceParams p;
  p.inscribed_radius = 0.3;
  p.min_clearance = 0.05;
  p.clearance_band = 0.2;
  p.band_conductance = 0.1;
  const ConfigSpace cs(m, p);
  // Row iy: gap to the wall edge = (iy - 0.5) * 0.05 (the map's far edge is 1.95 m away).
  for (int iy = 1; iy < 20; ++iy) {
    const double clearance = (iy - 0.5) * 0.05 - 0.3;
    if (clearance <= 0.05) {
      EXPECT_FALSE(cs.isFree(100, iy));
    } else if (clearance >= 0.2) {
      EXPECT_FLOAT_EQ(cs.conductance(100, iy), 1.0f);
    } else {
      EXPECT_GT(cs.conductance(100, iy), 0.1f);
      EXPECT_LT(cs.conductance(100, iy), 1.0f);
      EXPECT_GT(cs.conductance(100, iy + 1), cs.conductance(100, iy));
    }
  }
}

TEST(ConfigSpace, RejectsBadInput) {
  ConfigSpaceParams p;
  p.min_clearance = std::nan("");
  EXPECT_THROW(ConfigSpace(freeMap(10, 10, 0.05), p), std::invalid_argument);
  OccupancyMap bad = freeMap(10, 10, 0.05);
  bad.data.pop_back();
  EXPECT_THROW(ConfigSpace(bad, ConfigSpaceParams()), std::invalid_argument);
}
