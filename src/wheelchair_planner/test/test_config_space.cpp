// The C-space: dilation radius, unknown cells, conductance of the clearance band, the in-place
// update after a map change.
#include <wheelchair_planner/config_space.h>
#include <wheelchair_planner_test/maze.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

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

namespace {

/// `actual` holds exactly what a C-space built afresh from the same map holds.
void expectSameCspace(const ConfigSpace& expected, const ConfigSpace& actual) {
  ASSERT_EQ(expected.width(), actual.width());
  ASSERT_EQ(expected.height(), actual.height());
  for (int iy = 0; iy < expected.height(); ++iy) {
    for (int ix = 0; ix < expected.width(); ++ix) {
      ASSERT_EQ(expected.isFree(ix, iy), actual.isFree(ix, iy)) << ix << "," << iy;
      ASSERT_FLOAT_EQ(expected.obstacleDistance(ix, iy), actual.obstacleDistance(ix, iy))
          << ix << "," << iy;
      ASSERT_FLOAT_EQ(expected.conductance(ix, iy), actual.conductance(ix, iy)) << ix << "," << iy;
    }
  }
}

/// The cells whose free state or conductance differ between two C-spaces of one grid.
std::vector<size_t> differingCells(const ConfigSpace& a, const ConfigSpace& b) {
  std::vector<size_t> cells;
  for (int iy = 0; iy < a.height(); ++iy)
    for (int ix = 0; ix < a.width(); ++ix)
      if (a.isFree(ix, iy) != b.isFree(ix, iy) || a.conductance(ix, iy) != b.conductance(ix, iy))
        cells.push_back(a.index(ix, iy));
  return cells;
}

void fillSquare(OccupancyMap& m, int x, int y, int size, int8_t value) {
  for (int iy = std::max(0, y); iy < std::min(m.height, y + size); ++iy)
    for (int ix = std::max(0, x); ix < std::min(m.width, x + size); ++ix) m.at(ix, iy) = value;
}

}  // namespace

// Obstacles of 1 to 20 cells dropped on a maze and on an open room and taken away again, one
// after the other: after each update the C-space equals one built afresh from that map, and the
// reported cells are exactly those whose free state or conductance changed.
TEST(ConfigSpace, UpdateEqualsAFreshCspaceAfterObstaclesAppearAndGo) {
  std::mt19937 rng(3);
  for (const OccupancyMap& base : {makeMaze(160, 18, 4, 5), freeMap(120, 90, 0.05)}) {
    ConfigSpace cs(base, ConfigSpaceParams());
    OccupancyMap current = base;
    std::vector<std::array<int, 3>> dropped;  // x, y, size
    int windowed = 0;
    for (int step = 0; step < 24; ++step) {
      OccupancyMap next = current;
      if (dropped.empty() || rng() % 3 != 0) {
        std::array<int, 3> o{static_cast<int>(rng() % base.width),
                             static_cast<int>(rng() % base.height),
                             1 + static_cast<int>(rng() % 20)};
        fillSquare(next, o[0], o[1], o[2], wheelchair_core::kOccupied);
        dropped.push_back(o);
      } else {  // the oldest one goes: its cells back to the base map's
        const auto o = dropped.front();
        dropped.erase(dropped.begin());
        for (int iy = std::max(0, o[1]); iy < std::min(base.height, o[1] + o[2]); ++iy)
          for (int ix = std::max(0, o[0]); ix < std::min(base.width, o[0] + o[2]); ++ix)
            next.at(ix, iy) = base.at(ix, iy);
        for (const auto& d : dropped)
          fillSquare(next, d[0], d[1], d[2], wheelchair_core::kOccupied);
      }
      const ConfigSpace before(current, ConfigSpaceParams());
      const ConfigSpace fresh(next, ConfigSpaceParams());
      const ConfigSpaceChange change = cs.update(next);
      expectSameCspace(fresh, cs);
      if (!change.rebuilt) {
        ++windowed;
        EXPECT_EQ(change.cells, differingCells(before, fresh)) << "step " << step;
      }
      current = next;
    }
    EXPECT_GE(windowed, 20);  // removals that open space farther than before rebuild
  }
}

// A pillar taken out of a room leaves a spot farther from every obstacle than any cell was: the
// window's bound no longer holds and the C-space is rebuilt (still exact); the same map again
// changes nothing; another grid size is rebuilt.
TEST(ConfigSpace, UpdateRebuildsWhereTheWindowCannotBeExact) {
  OccupancyMap room = freeMap(100, 100, 0.05);
  fillSquare(room, 45, 45, 10, wheelchair_core::kOccupied);
  ConfigSpace cs(room, ConfigSpaceParams());
  const int revision = cs.revision();
  EXPECT_FALSE(cs.update(room).distancesChanged());
  EXPECT_EQ(cs.revision(), revision);
  const OccupancyMap empty = freeMap(100, 100, 0.05);
  const ConfigSpaceChange change = cs.update(empty);
  EXPECT_TRUE(change.rebuilt);
  EXPECT_EQ(cs.revision(), revision + 1);
  expectSameCspace(ConfigSpace(empty, ConfigSpaceParams()), cs);
  const OccupancyMap other = freeMap(80, 100, 0.05);
  EXPECT_TRUE(cs.update(other).rebuilt);
  expectSameCspace(ConfigSpace(other, ConfigSpaceParams()), cs);
}
